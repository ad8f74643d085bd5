# Task: place the brown mug beside the blue cup
# Plan:
# 1. Find a free place on the table beside the blue cup.
# 2. Pick up the brown mug and put it down there.
detect_objects()


def spot_beside(target, name, obstacles):
    """A free place on the table right beside `target` for `name`: left, right, nearer or farther, the first
    side where `name` clears every obstacle and stays within the arm's comfortable reach."""
    box, mine = get_3d_bbox(target), get_3d_bbox(name)
    center, half = (box[:2] + box[3:5]) / 2, (mine[3:5] - mine[:2]) / 2
    others = [get_3d_bbox(o) for o in obstacles]
    for side in ([0, 1], [0, -1], [-1, 0], [1, 0]):
        side = np.array(side, dtype=float)
        spot = center + side * ((box[3:5] - box[:2]) / 2 + half + 0.03)
        low, high = spot - half - 0.015, spot + half + 0.015
        if any(low[0] < o[3] and o[0] < high[0] and low[1] < o[4] and o[1] < high[1] for o in others):
            continue
        if 0.3 < np.linalg.norm(spot - np.array([-0.45, 0.0])) < 0.7:
            return np.array([spot[0], spot[1], mine[2]])
    raise ValueError(f'no free spot beside {target} for {name}')


def pick(name):
    """Grasps `name` from above where its shape allows, and lifts it clear of what is around it."""
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


def put(name, place_pose):
    """Carries the held `name` to `place_pose`, lets go of it and moves the hand up and away."""
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


spot = spot_beside('blue_cup', 'brown_mug', ['blue_bowl', 'lemon', 'cabinet'])
pick('brown_mug')
put('brown_mug', parse_place_pose(object_name='brown_mug', position=spot))
