# Task: move the golf ball into the blue bowl.
# Plan:
# 1. Detect the golf ball and the blue bowl.
# 2. Grasp the golf ball with the adaptive grasp, close the gripper, attach it and lift it.
# 3. Get a place pose inside the blue bowl, move there, release the ball, move up.
detect_objects(['golf_ball', 'blue_bowl'])
open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('golf_ball')
grasp(grasp_pose)
close_gripper()
attach_object('golf_ball')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose('golf_ball', 'blue_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('golf_ball')
move_in_direction([0, 0, 1], 0.1)
