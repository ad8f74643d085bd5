# query: objects = [table, cabinet, cabinet.drawer_0, cabinet.handle_0] ; # close the open drawer
# Plan:
# 1. Grasp the handle of the open drawer horizontally and attach the drawer.
# 2. Push along the joint axis, the opposite way from opening, by about as far as it is open.
# 3. Release and back away.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.drawer_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='prismatic')
move_in_direction(joint['joint_axis'], -0.2)
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(joint['joint_axis'], 0.05)
