# Task: move the tea box into the basket.
# Plan:
# 1. Detect the tea box and the basket.
# 2. Grasp the tea box with the adaptive grasp, close the gripper, attach it, lift it above the basket rim.
# 3. Get a place pose inside the basket, move there, release the box, move up.
detect_objects(['tea_box', 'basket'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('tea_box'))
close_gripper()
attach_object('tea_box')
move_in_direction([0, 0, 1], 0.15)
place_pose = parse_place_pose('tea_box', 'basket')
move_to_pose(place_pose)
open_gripper()
detach_object('tea_box')
move_in_direction([0, 0, 1], 0.1)
