# Task: open the second drawer of the cabinet and put the baseball into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Find the drawer's prismatic joint near the handle and pull along its axis to open it.
# 4. Release the handle and back away along the same axis.
# 5. Detect again, since the drawer moved.
# 6. Grasp the baseball from above, lift it.
# 7. Place it into the open drawer, release it, move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.22)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='baseball', description='center'))
close_gripper()
attach_object('baseball')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='baseball', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('baseball')
move_in_direction([0, 0, 1], 0.08)
