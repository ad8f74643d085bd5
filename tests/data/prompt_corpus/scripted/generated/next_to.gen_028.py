# Task: place the brown ceramic cup beside the pear.
# Plan:
# 1. Detect everything.
# 2. "Beside" means to the left (+y) or right (-y) of the pear: the cup's centre goes that far from the
#    pear's centre that their boxes are a small gap apart.
# 3. Of the two sides, choose the one on the table that is farther from the other objects (not the pear,
#    not the cup itself, which will move).
# 4. Grasp the cup with the adaptive grasp from above (by its rim; a cup may be wider than the
#    fingers open), close the gripper, attach it and lift it.
# 5. Place it at the chosen spot, open the gripper, detach it and move up.

OBJECT = 'brown_ceramic_cup'
ANCHOR = 'pear'
GAP_M = 0.03
TABLE_EDGE_MARGIN_M = 0.05
LIFT_HEIGHT_M = 0.10
RETREAT_HEIGHT_M = 0.10
UP = [0, 0, 1]
DOWN = [0, 0, -1]


def half_size(name: str) -> np.ndarray:
    """Half the object's box extent along x and y."""
    box = get_3d_bbox(name)
    return np.array([box[3] - box[0], box[4] - box[1]]) / 2.0


def distance_to_footprint(point: np.ndarray, name: str) -> float:
    """Horizontal distance from a point to the object's box seen from above (0 inside it)."""
    box = get_3d_bbox(name)
    dx = max(box[0] - point[0], 0.0, point[0] - box[3])
    dy = max(box[1] - point[1], 0.0, point[1] - box[4])
    return float(np.hypot(dx, dy))


def on_table(point: np.ndarray) -> bool:
    """True where the point lies on the table top, away from its edges."""
    box = get_3d_bbox('table')
    return (box[0] + TABLE_EDGE_MARGIN_M <= point[0] <= box[3] - TABLE_EDGE_MARGIN_M
            and box[1] + TABLE_EDGE_MARGIN_M <= point[1] <= box[4] - TABLE_EDGE_MARGIN_M)


def clearance(point: np.ndarray) -> float:
    """Distance from the point to the nearest other object on the table."""
    others = [
        name for name in get_object_name_list()
        if name not in ('table', OBJECT, ANCHOR) and name.split('.')[0] != 'cabinet'
    ]
    return min((distance_to_footprint(point, name) for name in others), default=float('inf'))


def choose_spot() -> np.ndarray:
    """The spot beside the pear, left or right, with the more room around it."""
    anchor = get_object_center_position(ANCHOR)
    offset = half_size(ANCHOR)[1] + max(half_size(OBJECT)) + GAP_M
    candidates = [anchor + np.array([0.0, side * offset, 0.0]) for side in (1.0, -1.0)]
    usable = [spot for spot in candidates if on_table(spot)] or candidates
    best = max(usable, key=clearance)
    side = 'left' if best[1] > anchor[1] else 'right'
    print(f'Placing {OBJECT} to the {side} of the {ANCHOR}, {offset:.2f} m from its centre')
    return best


def pick(name: str) -> None:
    """Grasp the cup from above by the adaptive grasp, attach it and lift it."""
    print(f'Picking {name}')
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=DOWN))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_at(name: str, position: np.ndarray) -> None:
    """Set the held object down at the position, release it and move up."""
    move_to_pose(parse_place_pose(object_name=name, position=list(position)))
    open_gripper()
    detach_object(name)
    move_in_direction(UP, RETREAT_HEIGHT_M)


def main() -> None:
    """Put the cup next to the pear."""
    detect_objects()
    spot = choose_spot()
    pick(OBJECT)
    place_at(OBJECT, spot)
    print(f'Done: {OBJECT} is beside the {ANCHOR}')


if __name__ == "__main__":
    main()
