# Task: put the rubiks cube into the top drawer; the drawer is closed, open it first.
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0.
# 2. Grasp the handle horizontally, attach the drawer, pull it along its prismatic axis almost fully open.
# 3. Release the handle, back away, and look at the drawer again now that it moved.
# 4. Pick the rubiks cube from above, lift it, place it into the open drawer, release, move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.drawer_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.9 * (joint['joint_upper'] - joint['joint_value']))
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects(object_list=['cabinet.drawer_0', 'cabinet.handle_0'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='rubiks_cube', description='center'))
close_gripper()
attach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='rubiks_cube', receptacle_name='cabinet.drawer_0'))
open_gripper()
detach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.08)
