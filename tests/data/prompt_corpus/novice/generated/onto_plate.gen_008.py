# Task: place the green cup onto the blue plate.
# Plan:
# 1. Detect the green cup and the blue plate.
# 2. Grasp the cup with the adaptive grasp from above (its rim), lift it.
# 3. Place it onto the blue plate, release it, move up.
detect_objects(object_list=['green_cup', 'blue_plate'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='green_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('green_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='green_cup', receptacle_name='blue_plate'))
open_gripper()
detach_object('green_cup')
move_in_direction([0, 0, 1], 0.1)
