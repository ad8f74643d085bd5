# Task: stack the green block on top of the red box.
# Plan:
# 1. Detect the green block and the red box.
# 2. Grasp the green block from above, lift it higher than the red box.
# 3. Place it on top of the red box, release it, move up.
detect_objects(['green_block', 'red_box'])
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('green_block', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('green_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose('green_block', 'red_box'))
open_gripper()
detach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
