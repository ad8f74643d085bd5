# Task: swap the positions of the green block and the lemon.
# Plan:
# 1. Detect everything and remember both objects' centres before anything moves.
# 2. Find a temporary spot for the green block: try spots 20-30 cm from it (towards the robot, left, right, away)
#    and take the first whose footprint (the block's box) is on the table, clear of every other object's box and
#    far enough from the block's old centre that the lemon, set down there later, will not reach it.
# 3. Move the block there, so that its place is free.
# 4. Move the lemon to the block's old centre, then the block to the lemon's old centre.
# Each move: grasp top-down at the middle, attach, lift with a Pose from the gripper's, place at the position on
# the table, release, move up.
detect_objects()
block_at = np.array(get_object_center_position('green_block'))
lemon_at = np.array(get_object_center_position('lemon'))
table_box = get_3d_bbox('table')
table_top = table_box[5]


def spot_is_free(x, y, half_x, half_y, ignore):
    # The footprint around (x, y) must lie on the table and keep 2 cm from every other object's box.
    if x - half_x < table_box[0] + 0.02 or x + half_x > table_box[3] - 0.02:
        return False
    if y - half_y < table_box[1] + 0.02 or y + half_y > table_box[4] - 0.02:
        return False
    for other in get_object_name_list():
        if other == 'table' or other in ignore:
            continue
        b = get_3d_bbox(other)
        if x + half_x > b[0] - 0.02 and x - half_x < b[3] + 0.02 and y + half_y > b[1] - 0.02 and y - half_y < b[4] + 0.02:
            return False
    return True


def move_object(name, position):
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    lift = get_gripper_pose()
    lift.position.z += 0.1
    move_to_pose(lift)
    move_to_pose(parse_place_pose(object_name=name, position=[position[0], position[1], table_top]))
    open_gripper()
    detach_object(name)
    up = get_gripper_pose()
    up.position.z += 0.1
    move_to_pose(up)


block_box = get_3d_bbox('green_block')
half_x = (block_box[3] - block_box[0]) / 2.0
half_y = (block_box[4] - block_box[1]) / 2.0
lemon_box = get_3d_bbox('lemon')
keep_off = max(lemon_box[3] - lemon_box[0], lemon_box[4] - lemon_box[1]) / 2.0 + max(half_x, half_y) + 0.02
offsets = [[-0.2, 0.0], [0.0, 0.2], [0.0, -0.2], [-0.3, 0.0], [0.0, 0.3], [0.0, -0.3], [0.2, 0.0], [0.3, 0.0]]
temp = [block_at[0] - 0.2, block_at[1]]
for dx, dy in offsets:
    x, y = block_at[0] + dx, block_at[1] + dy
    far_enough = np.hypot(x - block_at[0], y - block_at[1]) > keep_off
    if far_enough and spot_is_free(x, y, half_x, half_y, ['green_block']):
        temp = [x, y]
        break

move_object('green_block', temp)
move_object('lemon', block_at)
move_object('green_block', lemon_at)
