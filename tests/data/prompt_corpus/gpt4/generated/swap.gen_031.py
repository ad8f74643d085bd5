# Task: exchange the places of the yellow mug and the banana.
# Plan:
# 1. Detect the objects and remember where the yellow mug and the banana are before anything moves.
# 2. Compute a free parking spot on the table, 20 cm to the side of the line between them
#    (the side nearer the table's centre).
# 3. Move the yellow mug to the parking spot.
# 4. Move the banana to where the mug was.
# 5. Move the yellow mug to where the banana was.
detect_objects()
mug_pos = get_object_center_position('yellow_mug')
banana_pos = get_object_center_position('banana')
table_center = get_object_center_position('table')


def parking_position(p1, p2, distance=0.2):
    mid = (p1 + p2) / 2
    d = p2 - p1
    perp = np.array([-d[1], d[0], 0.0])
    perp = perp / (np.linalg.norm(perp) + 1e-9)
    cand_a = mid + distance * perp
    cand_b = mid - distance * perp
    if np.linalg.norm(cand_a[:2] - table_center[:2]) < np.linalg.norm(cand_b[:2] - table_center[:2]):
        return cand_a
    return cand_b


def move_object(obj, position, receptacle=None):
    open_gripper()
    if 'mug' in obj:
        grasp(parse_adaptive_shape_grasp_pose(obj, preferred_approach_direction=[0, 0, -1]))
    else:
        grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, receptacle, position))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


park = parking_position(mug_pos, banana_pos)
move_object('yellow_mug', park, 'table')
move_object('banana', mug_pos)
move_object('yellow_mug', banana_pos)
