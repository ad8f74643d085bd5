# Task: place the medication bottle in the footed bowl
# Plan:
# 1. Detect the medication bottle and the footed bowl.
# 2. Grasp the narrow bottle from above at its middle, lift it well clear (the footed bowl stands high).
# 3. Place it into the footed bowl, release it, move up.
detect_objects(object_list=['medication_bottle', 'footed_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='medication_bottle', description='center'))
close_gripper()
attach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='medication_bottle', receptacle_name='footed_bowl'))
open_gripper()
detach_object('medication_bottle')
move_in_direction([0, 0, 1], 0.1)
