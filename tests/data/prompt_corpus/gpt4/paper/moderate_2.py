# Task: place the mug into the second top drawer; the drawer is closed, so open it first.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, attach the drawer and pull it open along its prismatic joint axis.
# 3. Release the handle, back away and detect again since the drawer moved.
# 4. Grasp the white_and_yellow_mug by its rim from above, lift it.
# 5. Place it into the open drawer, release it, move up.
detect_objects()

open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
joint_info = get_object_joint_info('cabinet', get_object_center_position('cabinet.handle_1'), 'prismatic')
axis = np.array(joint_info['joint_axis'])
move_in_direction(axis, min(0.25, joint_info['joint_upper'] - joint_info['joint_value']))
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(axis, 0.05)
detect_objects()

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('white_and_yellow_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_and_yellow_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('white_and_yellow_mug', 'cabinet.drawer_1'))
open_gripper()
detach_object('white_and_yellow_mug')
move_in_direction([0, 0, 1], 0.08)
