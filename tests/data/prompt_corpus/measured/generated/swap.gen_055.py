# Task: swap the positions of the lime and the plum.
# Plan:
# 1. Detect; remember the centres of the lime and the plum before anything moves.
# 2. Compute a temporary spot for the lime: on rings 18-30 cm around it, on the table, reachable (0.3 to 0.75 m
#    from the base at x = -0.45, y = 0), at least 15 cm from both remembered spots, clear of the other objects'
#    boxes (the first with 4 cm clearance, else the clearest); if none, let parse_place_pose pick a spot aside.
# 3. Move the lime there, then the plum to the lime's old spot, then the lime to the plum's old spot; each move
#    re-detects, grasps from above, lifts, and places the object's middle over the given (x, y).
# 4. Detect again and print how far each ended from its target.

BASE = np.array([-0.45, 0.0])


def footprint_gap(x, y, hx, hy, box):
    # Horizontal distance between a footprint centred at (x, y) with half sizes hx, hy and a box.
    dx = max(box[0] - (x + hx), (x - hx) - box[3], 0.0)
    dy = max(box[1] - (y + hy), (y - hy) - box[4], 0.0)
    return float(np.hypot(dx, dy))


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def free_spot(name, keep_free):
    box = get_3d_bbox(name)
    hx, hy = (box[3] - box[0]) / 2, (box[4] - box[1]) / 2
    start = get_object_center_position(name)
    table = get_3d_bbox('table')
    others = [n for n in get_object_name_list() if n not in ('table', name) and not n.startswith('cabinet')]
    obstacles = [get_3d_bbox(n) for n in others]
    best, best_gap = None, -1.0
    for r in [0.18, 0.22, 0.26, 0.30]:
        for a in np.linspace(0.0, 2 * np.pi, 16, endpoint=False):
            x, y = start[0] + r * np.cos(a), start[1] + r * np.sin(a)
            if (x - hx < table[0] + 0.03 or x + hx > table[3] - 0.03
                    or y - hy < table[1] + 0.03 or y + hy > table[4] - 0.03):
                continue
            reach = np.hypot(x - BASE[0], y - BASE[1])
            if reach < 0.3 or reach > 0.75:
                continue
            if min(np.hypot(x - p[0], y - p[1]) for p in keep_free) < 0.15:
                continue
            clearance = min([footprint_gap(x, y, hx, hy, b) for b in obstacles] + [1.0])
            if clearance >= 0.04:
                return np.array([x, y, table[5]])
            if clearance > best_gap:
                best, best_gap = np.array([x, y, table[5]]), clearance
    return best


def move_object(name, position):
    detect_objects()
    open_gripper()
    grasp(top_grasp_pose(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    if position is None:
        place = parse_place_pose(object_name=name, receptacle_name='table')
    else:
        place = parse_place_pose(object_name=name, position=list(position))
    move_to_pose(place)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    print('moved', name)


detect_objects()
lime_at = get_object_center_position('lime')
plum_at = get_object_center_position('plum')
print('lime at', np.round(lime_at, 3), 'plum at', np.round(plum_at, 3))
temp = free_spot('lime', [lime_at, plum_at])
print('temporary spot for the lime:', None if temp is None else np.round(temp, 3))

move_object('lime', temp)
move_object('plum', lime_at)
move_object('lime', plum_at)

detect_objects()
for name, goal in [('plum', lime_at), ('lime', plum_at)]:
    c = get_object_center_position(name)
    print(name, 'ended', round(float(np.hypot(c[0] - goal[0], c[1] - goal[1])), 3), 'm from its target')
