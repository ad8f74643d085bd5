# Task: put the blue box into the second drawer; the drawer is closed, open it first
# Plan:
# 1. Two drawers above a door: the second drawer is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle, attach the drawer, pull it open along its joint axis, release, back away.
# 3. Detect again, now that the drawer is open.
# 4. Grasp the blue box from above, lift it, place it into the open drawer, release, move up.
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
grasp(parse_central_lift_grasp_pose(object_name='blue_box', description='center'))
close_gripper()
attach_object('blue_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_box', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('blue_box')
move_in_direction([0, 0, 1], 0.08)
