# Task: put the rubiks cube into the green bowl
# Plan:
# 1. Detect the rubiks cube and the green bowl.
# 2. Grasp the cube from above at its middle, lift it.
# 3. Place it into the green bowl, release it, move up.
detect_objects(object_list=['rubiks_cube', 'green_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='rubiks_cube', description='center'))
close_gripper()
attach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='rubiks_cube', receptacle_name='green_bowl'))
open_gripper()
detach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.1)
