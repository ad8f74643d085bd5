# Task: open the cabinet door and put the rubiks cube in the cupboard behind it.
# Plan:
# 1. Detect everything. The door is on the top row, so its handle is cabinet.handle_0 (handle_1 is the drawer's).
# 2. Grasp the handle horizontally, close, attach the door.
# 3. Swing it open about its revolute joint by up to 90 degrees (at least the 40 the compartment needs), release, back out.
# 4. Detect again, since the door moved and the compartment is measured anew.
# 5. Grasp the cube with a horizontal grasp (needed to carry it level into the compartment), close, attach, lift.
# 6. Place it into the compartment behind cabinet.door_0 and release it (the hand backs out the way it came).
zax = lambda q: np.array([2 * (q.x * q.z + q.w * q.y), 2 * (q.y * q.z - q.w * q.x), 1 - 2 * (q.x ** 2 + q.y ** 2)])
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_0'))
close_gripper()
attach_object('cabinet.door_0')
j = get_object_joint_info('cabinet.door_0', get_object_center_position('cabinet.handle_0'), 'revolute')
follow_path(generate_arc_path_around_joint(get_gripper_pose(), j['joint_axis'], j['joint_position'], 20, min(90, j['joint_upper'] - j['joint_value'])))
open_gripper()
detach_object('cabinet.door_0')
move_in_direction(zax(get_gripper_pose().orientation), -0.08)
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose('rubiks_cube'))
close_gripper()
attach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('rubiks_cube', 'cabinet.door_0'))
open_gripper()
detach_object('rubiks_cube')
