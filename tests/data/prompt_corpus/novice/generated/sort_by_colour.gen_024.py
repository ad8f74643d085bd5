# Task: sort the objects on the table by colour: put the red objects on the red plate.
# Plan:
# 1. Colours are known only from the names. The red objects on the table are those whose name says red,
#    other than the red plate itself: only red_cup (the apple's name gives no colour).
# 2. Grasp the red cup with the adaptive grasp from above (its rim), lift it.
# 3. Place it onto the red plate, release it, move up.
detect_objects()
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='red_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('red_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='red_cup', receptacle_name='red_plate'))
open_gripper()
detach_object('red_cup')
move_in_direction([0, 0, 1], 0.1)
