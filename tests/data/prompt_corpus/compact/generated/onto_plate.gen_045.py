# Task: place the lemon onto the blue plate
# Plan:
# 1. Detect the lemon and the blue plate.
# 2. Grasp the lemon from above at its middle, lift it.
# 3. Place it onto the blue plate, release it, move up.
detect_objects(object_list=['lemon', 'blue_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='lemon', description='center'))
close_gripper()
attach_object('lemon')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='lemon', receptacle_name='blue_plate'))
open_gripper()
detach_object('lemon')
move_in_direction([0, 0, 1], 0.1)
