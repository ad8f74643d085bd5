# Task: exchange the positions of the apple and the banana on the table.
# Plan:
# 1. Detect everything and remember both fruits' centres before anything moves.
# 2. Find a temporary spot for the apple: try spots 20-30 cm from it (towards the robot, left, right, away) and
#    take the first whose footprint (the apple's box) is on the table, clear of every other object's box and far
#    enough from the apple's old centre that the banana, set down there later, will not reach it.
# 3. Move the apple there, so that its place is free.
# 4. Move the banana to the apple's old centre, then the apple to the banana's old centre.
# Each move: grasp (top-down at the middle if narrower than the fingers open, else the adaptive grasp), attach,
# lift with a Pose from the gripper's, place at the position on the table, release, move up.
detect_objects()
apple_at = np.array(get_object_center_position('apple'))
banana_at = np.array(get_object_center_position('banana'))
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
    b = get_3d_bbox(name)
    if min(b[3] - b[0], b[4] - b[1]) < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])


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


apple_box = get_3d_bbox('apple')
half_x = (apple_box[3] - apple_box[0]) / 2.0
half_y = (apple_box[4] - apple_box[1]) / 2.0
banana_box = get_3d_bbox('banana')
keep_off = max(banana_box[3] - banana_box[0], banana_box[4] - banana_box[1]) / 2.0 + max(half_x, half_y) + 0.02
offsets = [[-0.2, 0.0], [0.0, 0.2], [0.0, -0.2], [-0.3, 0.0], [0.0, 0.3], [0.0, -0.3], [0.2, 0.0], [0.3, 0.0]]
temp = [apple_at[0] - 0.2, apple_at[1]]
for dx, dy in offsets:
    x, y = apple_at[0] + dx, apple_at[1] + dy
    far_enough = np.hypot(x - apple_at[0], y - apple_at[1]) > keep_off
    if far_enough and spot_is_free(x, y, half_x, half_y, ['apple']):
        temp = [x, y]
        break

move_object('apple', temp)
move_object('banana', apple_at)
move_object('apple', banana_at)
