# Task: sort the objects on the table by colour: put the blue objects on the blue plate.
# Plan:
# 1. The blue objects: blue_cup to move; blue_plate is the receptacle and blue_saucer stays where it is.
# 2. Grasp the blue cup with the adaptive grasp from above, lift it.
# 3. Place it on the blue plate, release it, move up.
detect_objects()
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='blue_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('blue_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_cup', receptacle_name='blue_plate'))
open_gripper()
detach_object('blue_cup')
move_in_direction([0, 0, 1], 0.1)
