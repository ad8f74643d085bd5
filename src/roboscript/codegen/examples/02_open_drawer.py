# query: objects = [table, cabinet, cabinet.drawer_0, cabinet.drawer_1, cabinet.handle_0, cabinet.handle_1] ; # open the top drawer
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0.
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Find the drawer's prismatic joint near the handle and pull along its axis.
# 4. Release the handle and back away along the same axis.
detect_objects()
open_gripper()
handle_pose = parse_horizontal_grasp_pose(object_name='cabinet.handle_0')
grasp(handle_pose)
close_gripper()
attach_object('cabinet.drawer_0')
handle_position = get_object_center_position('cabinet.handle_0')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='prismatic')
move_in_direction(joint['joint_axis'], 0.2)
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(joint['joint_axis'], 0.05)
