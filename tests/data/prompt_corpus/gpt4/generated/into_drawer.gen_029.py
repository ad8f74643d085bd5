# Task: open the second drawer of the cabinet and put the medication bottle into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Get the drawer's prismatic joint near the handle and pull along its axis to open it.
# 4. Release the handle and back away; detect again since the drawer moved.
# 5. Grasp the medication bottle, lift it, place it into the open drawer, release, move up.
detect_objects()

# open the second drawer
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
handle_pos = get_object_center_position('cabinet.handle_1')
joint_info = get_object_joint_info('cabinet', handle_pos, 'prismatic')
pull_distance = min(0.2, joint_info['joint_upper'] - joint_info['joint_value'])
move_in_direction(joint_info['joint_axis'], pull_distance)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint_info['joint_axis'], 0.05)
detect_objects()

# put the medication bottle into the drawer
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('medication_bottle'))
close_gripper()
attach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('medication_bottle', 'cabinet.drawer_1'))
open_gripper()
detach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.08)
