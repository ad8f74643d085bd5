# Task: place the apple into the footed bowl.
# Plan:
# 1. Detect the apple and the footed bowl.
# 2. Grasp the apple with the adaptive grasp, close the gripper, attach it and lift it.
# 3. Get a place pose inside the footed bowl, move there, release the apple, move up.
detect_objects(['apple', 'footed_bowl'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('apple'))
close_gripper()
attach_object('apple')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose('apple', 'footed_bowl'))
open_gripper()
detach_object('apple')
move_in_direction([0, 0, 1], 0.1)
