# Task: open the second drawer of the cabinet and put the red block into it.
# Plan:
# 1. The second drawer is cabinet.drawer_1, its handle cabinet.handle_1: grasp the handle, attach the drawer, pull it open.
# 2. Release the handle, back away, and look again at the opened drawer.
# 3. Grasp the red block from above, lift it.
# 4. Place it into the open drawer, release it, move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.2)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects()
grasp(parse_central_lift_grasp_pose(object_name='red_block', description='center'))
close_gripper()
attach_object('red_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='red_block', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('red_block')
move_in_direction([0, 0, 1], 0.08)
