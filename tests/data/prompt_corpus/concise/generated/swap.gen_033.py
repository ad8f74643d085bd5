# Task: exchange the places of the golf ball and the blue box.
# Plan:
# 1. Remember where the golf ball and the blue box stand before anything moves.
# 2. Find a free spot on the table near the golf ball: the candidate farthest from every object's box
#    (the cabinet included), on the table, reachable and not too near the robot's base.
# 3. Move the golf ball there, the box to where the ball was, then the ball to where the box was.
detect_objects()
ball_at = get_object_center_position('golf_ball')
box_at = get_object_center_position('blue_box')
obstacles = [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet.')]


def clearance(p, names):
    # Smallest horizontal distance from p to the boxes of names.
    d = []
    for n in names:
        b = get_3d_bbox(n)
        d.append(np.hypot(max(b[0] - p[0], 0, p[0] - b[3]), max(b[1] - p[1], 0, p[1] - b[4])))
    return min(d)


def free_spot(around):
    table = get_3d_bbox('table')
    best, best_d = None, -1
    for dx, dy in [(-0.2, 0), (0, 0.2), (0, -0.2), (0.2, 0), (-0.15, 0.15), (-0.15, -0.15), (0.15, 0.15), (0.15, -0.15)]:
        p = np.array([around[0] + dx, around[1] + dy, around[2]])
        r = np.hypot(p[0], p[1])
        if not (table[0] + 0.05 < p[0] < table[3] - 0.05 and table[1] + 0.05 < p[1] < table[4] - 0.05) or r < 0.3 or r > 0.75:
            continue
        d = clearance(p, obstacles)
        if d > best_d:
            best, best_d = p, d
    if best is None:
        raise PlacementError('no free spot on the table near the golf ball')
    return best


def move_object(name, position):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


move_object('golf_ball', free_spot(ball_at))
move_object('blue_box', ball_at)
move_object('golf_ball', box_at)
