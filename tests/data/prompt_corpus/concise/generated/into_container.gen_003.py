# Task: move the golf ball into the basket.
# Plan:
# 1. Detect the golf ball and the basket.
# 2. Grasp the golf ball from above at its middle, lift it.
# 3. Place it into the basket, release it, move up.
detect_objects(object_list=['golf_ball', 'basket'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='golf_ball', description='center'))
close_gripper()
attach_object('golf_ball')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='golf_ball', receptacle_name='basket'))
open_gripper()
detach_object('golf_ball')
move_in_direction([0, 0, 1], 0.1)
