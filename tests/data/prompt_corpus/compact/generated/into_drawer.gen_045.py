# Task: open the second drawer of the cabinet and put the white mug into it
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1; with three drawers and no door its handle is cabinet.handle_1.
# 2. Grasp the handle horizontally, attach the drawer, pull it out along its prismatic joint, release, back away.
# 3. Detect the drawer again now that it is open.
# 4. Grasp the mug from above by its rim (adaptive grasp), lift it.
# 5. Place it into the open drawer, release it, move up.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.9 * (joint['joint_upper'] - joint['joint_value']))
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects(object_list=['cabinet.drawer_1', 'white_mug'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='white_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_mug', receptacle_name='cabinet.drawer_1'))
open_gripper()
detach_object('white_mug')
move_in_direction([0, 0, 1], 0.08)
