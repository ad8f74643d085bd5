# Task: set the red box down on the green plate.
# Plan:
# 1. Detect the red box and the green plate.
# 2. Grasp the red box with the adaptive grasp, close the gripper, attach it, lift it.
# 3. Get a place pose on the green plate, move there, release the box, move up.
detect_objects(['red_box', 'green_plate'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('red_box'))
close_gripper()
attach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('red_box', 'green_plate'))
open_gripper()
detach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
