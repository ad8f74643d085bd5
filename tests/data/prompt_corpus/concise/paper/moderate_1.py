# Task: move the white mug into a container with the same colour (colours are in the names).
# Plan:
# 1. The white porcelain mug is white; the only white container is the white ceramic plate.
# 2. Grasp the mug by its rim from above, lift it.
# 3. Place it onto the white ceramic plate, release it, move up.
detect_objects(object_list=['white_porcelain_mug', 'white_ceramic_plate'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='white_porcelain_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_porcelain_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_porcelain_mug', receptacle_name='white_ceramic_plate'))
open_gripper()
detach_object('white_porcelain_mug')
move_in_direction([0, 0, 1], 0.1)
