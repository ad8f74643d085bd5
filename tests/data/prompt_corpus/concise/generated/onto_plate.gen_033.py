# Task: set the white mug down on the yellow plate
# Plan:
# 1. Grasp the white mug with the adaptive grasp from above (its rim), lift it.
# 2. Place it onto the yellow plate, release it, move up.
detect_objects(object_list=['white_mug', 'yellow_plate'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='white_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_mug', receptacle_name='yellow_plate'))
open_gripper()
detach_object('white_mug')
move_in_direction([0, 0, 1], 0.1)
