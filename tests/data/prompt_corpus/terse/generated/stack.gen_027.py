# Task: put the wooden block on the brown box.
# Plan:
# 1. Detect the block and the box.
# 2. Grasp the block from above at its middle, close, attach, lift it higher than the box.
# 3. Place it on top of the brown box, release it and move up.
detect_objects(['wooden_block', 'brown_box'])
open_gripper()
grasp(parse_central_lift_grasp_pose('wooden_block', 'center'))
close_gripper()
attach_object('wooden_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose('wooden_block', 'brown_box'))
open_gripper()
detach_object('wooden_block')
move_in_direction([0, 0, 1], 0.1)
