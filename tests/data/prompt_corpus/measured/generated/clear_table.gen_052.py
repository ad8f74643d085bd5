# Task: clear the table by putting every object lying on it into the basket; the basket and the plate stay.
# Plan:
# 1. Detect; the objects to move are all names except the table, the cabinet, baskets, plates, saucers and
#    bowls: here gelatin_box, red_mug, toy_car, apple. Skip any whose centre already lies inside the basket's box.
# 2. Compute spots inside the basket so that the things do not land on each other: its box shrunk by 3 cm for
#    the walls, its centre for one object, else its quarter points.
# 3. For each object: re-detect, grasp (adaptive from above for a mug or cup, else central from above, adaptive
#    if that fails), lift until it clears the basket's rim, place at its spot in the basket, release, move up.
# 4. Detect again and print which objects lie inside the basket's box.

STAYS = ('basket', 'plate', 'saucer', 'bowl')


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


def spots_in(box, n, margin):
    c = box_centre(box)
    c[2] = box[2]
    if n <= 1:
        return [c]
    qx = max((box[3] - box[0]) / 2 - margin, 0.0) / 2
    qy = max((box[4] - box[1]) / 2 - margin, 0.0) / 2
    if n == 2:
        offsets = [(0.0, qy), (0.0, -qy)] if box[4] - box[1] >= box[3] - box[0] else [(qx, 0.0), (-qx, 0.0)]
    else:
        offsets = [(qx, qy), (qx, -qy), (-qx, qy), (-qx, -qy)]
    spots = [c + np.array([dx, dy, 0.0]) for dx, dy in offsets]
    return [spots[i % len(spots)] for i in range(n)]


def grasp_pose_for(name):
    if 'mug' in name or 'cup' in name:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def inside(c, box):
    return box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4]


detect_objects()
basket = get_3d_bbox('basket')
things = [n for n in get_object_name_list()
          if n != 'table' and not n.startswith('cabinet') and not any(word in n for word in STAYS)]
to_move = [n for n in things if not inside(get_object_center_position(n), basket)]
print('to put into the basket:', to_move)
spots = spots_in(basket, len(to_move), 0.03)

for name, spot in zip(to_move, spots):
    detect_objects()
    basket = get_3d_bbox('basket')
    box = get_3d_bbox(name)
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    # attach_object lifted it 5 cm; lift further so that its bottom is at least 5 cm above the basket's rim.
    move_in_direction([0, 0, 1], max(0.1, basket[5] - box[2]))
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket', position=list(spot)))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    print('put', name, 'into the basket near', np.round(spot, 3))

detect_objects()
basket = get_3d_bbox('basket')
for name in things:
    print(name, 'in the basket:', inside(get_object_center_position(name), basket))
