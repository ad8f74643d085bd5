# Task: sort the objects on the table by colour: put the blue objects on the blue plate
# Plan:
# 1. The blue objects besides the plate itself: only the blue block.
# 2. Grasp the blue block from above, lift it, place it onto the blue plate, release it, move up.
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='blue_block', description='center'))
close_gripper()
attach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='blue_plate'))
open_gripper()
detach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)
