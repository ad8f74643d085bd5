# Task: put the wooden block on the brown box.
# Plan:
# 1. Grasp the wooden block from above, lift it higher than the brown box.
# 2. Place it onto the brown box, release it, move up.
detect_objects(object_list=['wooden_block', 'brown_box'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='wooden_block', description='center'))
close_gripper()
attach_object('wooden_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='wooden_block', receptacle_name='brown_box'))
open_gripper()
detach_object('wooden_block')
move_in_direction([0, 0, 1], 0.1)
