# Task: put the medication bottle on the white saucer
# Plan:
# 1. Grasp the medication bottle from above at its middle, lift it.
# 2. Place it onto the white saucer, release it, move up.
detect_objects(object_list=['medication_bottle', 'white_saucer'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='medication_bottle', description='center'))
close_gripper()
attach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='medication_bottle', receptacle_name='white_saucer'))
open_gripper()
detach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.1)
