# Task: exchange the places of the green block and the strawberry.
# Plan:
# 1. Detect the objects and remember the positions of the green block and the strawberry.
# 2. Move the green block to a temporary spot on the table, 20 cm aside from the line between the two
#    (on the side nearer the table's centre), so that its place is free.
# 3. Move the strawberry to the green block's old position.
# 4. Move the green block to the strawberry's old position.
detect_objects()
block_pos = get_object_center_position('green_block')
berry_pos = get_object_center_position('strawberry')
table_center = get_object_center_position('table')

d = berry_pos - block_pos
perp = np.array([-d[1], d[0], 0.0])
perp = perp / (np.linalg.norm(perp) + 1e-9)
mid = (block_pos + berry_pos) / 2
temp_a = mid + 0.2 * perp
temp_b = mid - 0.2 * perp
temp_pos = temp_a if np.linalg.norm(temp_a[:2] - table_center[:2]) < np.linalg.norm(temp_b[:2] - table_center[:2]) else temp_b


def move_object(obj, position):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, position=position))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


move_object('green_block', temp_pos)
move_object('strawberry', block_pos)
move_object('green_block', berry_pos)
