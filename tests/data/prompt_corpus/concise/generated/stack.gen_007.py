# Task: place the red block on top of the brown box.
# Plan:
# 1. Grasp the red block from above, lift it higher than the brown box.
# 2. Place it onto the brown box, release it, move up.
detect_objects(object_list=['red_block', 'brown_box'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='red_block', description='center'))
close_gripper()
attach_object('red_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='red_block', receptacle_name='brown_box'))
open_gripper()
detach_object('red_block')
move_in_direction([0, 0, 1], 0.1)
