# Task: place the toy car in the basket.
# Plan:
# 1. Detect the toy car and the basket.
# 2. Grasp the toy car from above at its middle (across its narrow side), lift it.
# 3. Find a place pose inside the basket, move there, release, move up.
detect_objects(object_list=['toy_car', 'basket'])
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='toy_car', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('toy_car')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose(object_name='toy_car', receptacle_name='basket')
move_to_pose(place_pose)
open_gripper()
detach_object('toy_car')
move_in_direction([0, 0, 1], 0.1)
