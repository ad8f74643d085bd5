# query: objects = [table, cabinet, tuna_can, cabinet.drawer_0, cabinet.drawer_1, cabinet.handle_0, cabinet.handle_1] ; # put the can into the bottom drawer
# Plan:
# 1. The bottom drawer here is cabinet.drawer_1: open it by its handle first.
# 2. Pick the can from above.
# 3. Place it into the open drawer and release it.
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
grasp(parse_central_lift_grasp_pose(object_name='tuna_can', description='center'))
close_gripper()
attach_object('tuna_can')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='tuna_can', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('tuna_can')
move_in_direction([0, 0, 1], 0.08)
