# Task: clear the table by putting every object lying on it into the basket; leave the baskets,
# bowls and plates where they are.
# Plan:
# 1. Detect everything.
# 2. Make the list of objects to clear: every name except the table, the furniture and the receptacles
#    (baskets, bowls, plates, saucers), which cannot be picked up and stay where they are; skip anything
#    already lying in the basket.
# 3. Order them largest footprint first, so the smaller ones still find room in the basket.
# 4. For each object: open the gripper, grasp it (mugs and cups with the adaptive grasp from above, by
#    their rim; anything else top-down at its middle), close the gripper, attach it and lift it.
# 5. Place it into the basket, open the gripper, detach it and move up.

BASKET = 'basket'
RECEPTACLE_KINDS = ('basket', 'bowl', 'plate', 'saucer')
RIM_GRASP_KINDS = ('mug', 'cup')
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]
DOWN = [0, 0, -1]


def kinds_of(name: str) -> list:
    """The words of an object's name (``white_mug`` -> ``['white', 'mug']``)."""
    return name.split('_')


def is_furniture(name: str) -> bool:
    """True for the table, the cabinet and its parts."""
    return name == 'table' or name.split('.')[0] == 'cabinet'


def is_receptacle(name: str) -> bool:
    """True for baskets, bowls, plates and saucers, which stay where they are."""
    return any(kind in kinds_of(name) for kind in RECEPTACLE_KINDS)


def is_in_basket(name: str) -> bool:
    """True where the object's centre lies inside the basket's box."""
    x, y, z = get_object_center_position(name)
    x_min, y_min, z_min, x_max, y_max, z_max = get_3d_bbox(BASKET)
    return x_min <= x <= x_max and y_min <= y <= y_max and z_min <= z <= z_max


def footprint_area(name: str) -> float:
    """Area of the object's box seen from above, square metres."""
    x_min, y_min, _, x_max, y_max, _ = get_3d_bbox(name)
    return float((x_max - x_min) * (y_max - y_min))


def objects_to_clear() -> list:
    """Names of the pickable objects on the table that are not yet in the basket."""
    names = [
        name for name in get_object_name_list()
        if not is_furniture(name) and not is_receptacle(name)
    ]
    return [name for name in names if not is_in_basket(name)]


def grasp_pose_for(name: str) -> Pose:
    """A grasp suited to the object: mugs and cups by the rim from above, else top-down at the middle."""
    if any(kind in kinds_of(name) for kind in RIM_GRASP_KINDS):
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=DOWN)
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def pick(name: str) -> None:
    """Grasp the object, attach it and lift it."""
    print(f'Picking {name}')
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_into(name: str, receptacle: str) -> None:
    """Set the held object down in the receptacle, release it and move up."""
    print(f'Placing {name} into {receptacle}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Put every object on the table into the basket."""
    detect_objects()
    items = sorted(objects_to_clear(), key=footprint_area, reverse=True)
    print(f'Objects to clear: {items}')
    for name in items:
        pick(name)
        place_into(name, BASKET)
    print(f'Done: {len(items)} objects put into the {BASKET}')


if __name__ == "__main__":
    main()
