# Task: place the white medication bottle in the blue bowl.
# Plan:
# 1. Detect the bottle and the bowl.
# 2. Grasp the bottle from above at its middle, close, attach, lift it.
# 3. Place it into the blue bowl, release it and move up.
detect_objects(['white_medication_bottle', 'blue_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose('white_medication_bottle', 'center'))
close_gripper()
attach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('white_medication_bottle', 'blue_bowl'))
open_gripper()
detach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
