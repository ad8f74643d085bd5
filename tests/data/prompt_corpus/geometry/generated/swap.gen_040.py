# Task: swap the positions of the white mug and the white and pink box.
# Plan:
# 1. Detect everything and remember both objects' centres before anything moves.
# 2. Find a temporary spot for the mug: try spots 20-30 cm from it (towards the robot, left, right, away) and take
#    the first whose footprint (the mug's box) is on the table, clear of every other object's box and far enough
#    from the mug's old centre that the box, set down there later, will not reach it.
# 3. Move the mug there (adaptive grasp by its rim from above), so that its place is free.
# 4. Move the box to the mug's old centre (top-down at its middle if narrow enough, else the adaptive grasp).
# 5. Move the mug to the box's old centre.
# Each move: grasp, attach, lift with a Pose from the gripper's, place at the position on the table, release, up.
detect_objects()
mug_at = np.array(get_object_center_position('white_mug'))
box_at = np.array(get_object_center_position('white_and_pink_box'))
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


def grasp_pose_for(name):
    box = get_3d_bbox(name)
    if 'mug' in name or min(box[3] - box[0], box[4] - box[1]) >= 0.07:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def move_object(name, position):
    open_gripper()
    grasp(grasp_pose_for(name))
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


mug_box = get_3d_bbox('white_mug')
mug_half_x = (mug_box[3] - mug_box[0]) / 2.0
mug_half_y = (mug_box[4] - mug_box[1]) / 2.0
box_box = get_3d_bbox('white_and_pink_box')
# the box will land on the mug's old centre: keep the temporary spot farther from it than both half sizes
keep_off = max(box_box[3] - box_box[0], box_box[4] - box_box[1]) / 2.0 + max(mug_half_x, mug_half_y) + 0.02
offsets = [[-0.2, 0.0], [0.0, 0.2], [0.0, -0.2], [-0.3, 0.0], [0.0, 0.3], [0.0, -0.3], [0.2, 0.0], [0.3, 0.0]]
temp = [mug_at[0] - 0.2, mug_at[1]]
for dx, dy in offsets:
    x, y = mug_at[0] + dx, mug_at[1] + dy
    far_enough = np.hypot(x - mug_at[0], y - mug_at[1]) > keep_off
    if far_enough and spot_is_free(x, y, mug_half_x, mug_half_y, ['white_mug']):
        temp = [x, y]
        break

move_object('white_mug', temp)
move_object('white_and_pink_box', mug_at)
move_object('white_mug', box_at)
