# Task: move the strawberry into the red bowl.
# Plan:
# 1. Detect the strawberry and the red bowl.
# 2. Grasp the strawberry from above at its middle, lift it.
# 3. Find a place pose inside the red bowl, move there, release, move up.
detect_objects(object_list=['strawberry', 'red_bowl'])
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='strawberry', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose(object_name='strawberry', receptacle_name='red_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
