# Task: exchange the position of the apple and the banana on the table.
# Plan:
# 1. Detect the objects and record the apple's and the banana's positions.
# 2. Move the apple to a temporary free spot on the table, 20 cm aside from the line between the two
#    (on the side nearer the table's centre).
# 3. Move the banana to the apple's old position.
# 4. Move the apple to the banana's old position.
detect_objects()
apple_pos = get_object_center_position('apple')
banana_pos = get_object_center_position('banana')
table_center = get_object_center_position('table')

d = banana_pos - apple_pos
perp = np.array([-d[1], d[0], 0.0])
perp = perp / (np.linalg.norm(perp) + 1e-9)
mid = (apple_pos + banana_pos) / 2
temp_a = mid + 0.2 * perp
temp_b = mid - 0.2 * perp
if np.linalg.norm(temp_a[:2] - table_center[:2]) < np.linalg.norm(temp_b[:2] - table_center[:2]):
    temp_pos = temp_a
else:
    temp_pos = temp_b


def move_object(obj, receptacle, position):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, receptacle, position))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


move_object('apple', 'table', temp_pos)
move_object('banana', None, apple_pos)
move_object('apple', None, banana_pos)
