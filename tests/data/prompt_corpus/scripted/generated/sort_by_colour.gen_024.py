# Task: sort the objects on the table by colour: put the red objects on the red plate.
# Plan:
# 1. Detect everything.
# 2. The red objects are those whose name has the word "red" (names are the only colour information),
#    leaving out the table, the cabinet and its parts and the receptacles (plates, bowls, saucers,
#    baskets), which stay where they are. Here that is red_cup; "apple" names no colour, so it stays.
# 3. For each red object: grasp it (mugs and cups with the adaptive grasp from above, by their rim;
#    anything else top-down at its middle), close the gripper, attach it and lift it.
# 4. Place it on the red plate, open the gripper, detach it and move up.

COLOUR = 'red'
PLATE = 'red_plate'
RECEPTACLE_KINDS = ('basket', 'bowl', 'plate', 'saucer')
RIM_GRASP_KINDS = ('mug', 'cup')
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]
DOWN = [0, 0, -1]


def words_of(name: str) -> list:
    """The words of an object's name (``red_cup`` -> ``['red', 'cup']``)."""
    return name.split('_')


def is_furniture(name: str) -> bool:
    """True for the table, the cabinet and its parts."""
    return name == 'table' or name.split('.')[0] == 'cabinet'


def is_receptacle(name: str) -> bool:
    """True for plates, bowls, saucers and baskets, which stay where they are."""
    return any(kind in words_of(name) for kind in RECEPTACLE_KINDS)


def objects_of_colour(colour: str) -> list:
    """Pickable objects whose name says they have the given colour."""
    return [
        name for name in get_object_name_list()
        if not is_furniture(name) and not is_receptacle(name) and colour in words_of(name)
    ]


def grasp_pose_for(name: str) -> Pose:
    """A grasp suited to the object: mugs and cups by the rim from above, else top-down at the middle."""
    if any(kind in words_of(name) for kind in RIM_GRASP_KINDS):
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


def place_onto(name: str, receptacle: str) -> None:
    """Set the held object down on the receptacle, release it and move up."""
    print(f'Placing {name} onto {receptacle}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Put every red object on the red plate."""
    detect_objects()
    items = objects_of_colour(COLOUR)
    print(f'{COLOUR} objects: {items}')
    for name in items:
        pick(name)
        place_onto(name, PLATE)
    print(f'Done: {len(items)} objects put on the {PLATE}')


if __name__ == "__main__":
    main()
