# Grasp the handle of the second top drawer
open_gripper()
grasp_pose = parse_horizontal_grasp_pose('cabinet.handle_1')
grasp(grasp_pose)
close_gripper()
attach_object('cabinet.handle_1')

# Pull the drawer open, move in +x direction
move_in_direction([1, 0, 0], 0.25)

# Release the handle
open_gripper()
detach_object('cabinet.handle_1')

# Grasp the mug
grasp_pose = parse_adaptive_shape_grasp_pose('white_and_yellow_mug')
grasp(grasp_pose)
close_gripper()
attach_object('white_and_yellow_mug')

# Move the mug into the drawer and release it
place_pose = parse_place_pose('white_and_yellow_mug', 'cabinet.drawer_1')
move_to_pose(place_pose)
open_gripper()
detach_object('white_and_yellow_mug')
