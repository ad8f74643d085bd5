# Task: open the second drawer of the cabinet and put the blue block into it
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1. Handles are numbered by row with the door counted too,
#    so take the handle whose height is closest to the drawer's centre.
# 2. Grasp that handle horizontally, attach the drawer, pull it out along its prismatic joint, release, back away.
# 3. Detect the drawer again now that it is open.
# 4. Grasp the blue block from above, lift it.
# 5. Place it into the open drawer, release it, move up.
detect_objects()
drawer_z = get_object_center_position('cabinet.drawer_1')[2]
handle = min(['cabinet.handle_0', 'cabinet.handle_1', 'cabinet.handle_2'], key=lambda h: abs(get_object_center_position(h)[2] - drawer_z))
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object('cabinet.drawer_1')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')
move_in_direction(joint['joint_axis'], 0.9 * (joint['joint_upper'] - joint['joint_value']))
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects(object_list=['cabinet.drawer_1', 'blue_block'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='blue_block', description='center'))
close_gripper()
attach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('blue_block')
move_in_direction([0, 0, 1], 0.08)
