# Grasp the handle of the second top drawer
open_gripper()
grasp_pose = parse_horizontal_grasp_pose('cabinet.handle_1')
grasp(grasp_pose)
close_gripper()
attach_object('cabinet.handle_1')

# Pull the handle of the second top drawer, move in +x direction
direction = [1, 0, 0]  # (x, y, z)
move_in_direction(direction, distance=0.25)

# Release the handle
open_gripper()
detach_object('cabinet.handle_1')

# Put every box into the drawer
for box in ['white_and_pink_box', 'brown_box']:
    grasp_pose = parse_adaptive_shape_grasp_pose(box)
    grasp(grasp_pose)
    close_gripper()
    attach_object(box)
    place_pose = parse_place_pose(box, 'cabinet.drawer_1')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(box)
