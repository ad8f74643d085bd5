# Task: place the lime onto the pink saucer.
# Plan:
# 1. Detect the lime and the saucer.
# 2. Grasp the lime from above at its middle, close, attach, lift.
# 3. Place it onto the pink saucer, release it and move up.
detect_objects(['lime', 'pink_saucer'])
open_gripper()
grasp(parse_central_lift_grasp_pose('lime', 'center'))
close_gripper()
attach_object('lime')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('lime', 'pink_saucer'))
open_gripper()
detach_object('lime')
move_in_direction([0, 0, 1], 0.1)
