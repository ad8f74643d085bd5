# Task: put the toy car into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. Detect everything. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, close, attach the drawer; pull it along its prismatic axis as far as it opens.
# 3. Release, back away along the axis, and detect again since the drawer moved.
# 4. Grasp the toy car from above at its middle (across its narrow side), close, attach, lift.
# 5. Place it into the open drawer, release it and move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
j = get_object_joint_info('cabinet.drawer_1', get_object_center_position('cabinet.handle_1'), 'prismatic')
move_in_direction(j['joint_axis'], j['joint_upper'] - j['joint_value'])
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(j['joint_axis'], 0.05)
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose('toy_car', 'center'))
close_gripper()
attach_object('toy_car')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('toy_car', 'cabinet.drawer_1'))
open_gripper()
detach_object('toy_car')
move_in_direction([0, 0, 1], 0.08)
