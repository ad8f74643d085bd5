# Task: swing the cabinet door open.
# Plan:
# 1. Detect everything. The door is on the top row, so its handle is cabinet.handle_0 (handle_1 is the drawer's).
# 2. Grasp the handle horizontally, close, attach the door.
# 3. Get the door's revolute joint near the handle; follow an arc about the hinge by up to 90 degrees (less if it opens less).
# 4. Release and back the hand out along its approach axis.
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
