# Task: put the green block on the white saucer.
# Plan:
# 1. Detect the green block and the white saucer.
# 2. Grasp the green block from above, lift it.
# 3. Place it onto the saucer, release it, move up.
detect_objects(object_list=['green_block', 'white_saucer'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_block', description='center'))
close_gripper()
attach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='green_block', receptacle_name='white_saucer'))
open_gripper()
detach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
