# Task: open the top drawer of the cabinet and put the medication bottle into it.
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0: grasp the handle, attach the drawer, pull it open.
# 2. Release the handle, back away and look again at the opened drawer.
# 3. Pick the medication bottle from above and lift it.
# 4. Place it into the open drawer, release it, move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.drawer_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.2)
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects()
grasp(parse_central_lift_grasp_pose(object_name='medication_bottle', description='center'))
close_gripper()
attach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='medication_bottle', receptacle_name='cabinet.drawer_0'))
open_gripper()
detach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.08)
