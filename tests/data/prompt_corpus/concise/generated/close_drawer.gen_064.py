# Task: close the second drawer of the cabinet.
# Plan:
# 1. The second drawer is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Push along the joint axis (-axis) by as far as the drawer is open.
# 4. Release and back away.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
move_in_direction(joint['joint_axis'], -joint['joint_value'])
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint['joint_axis'], 0.05)
