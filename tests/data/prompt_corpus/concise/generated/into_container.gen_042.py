# Task: put the white medication bottle into the footed bowl
# Plan:
# 1. Detect the bottle and the bowl.
# 2. Grasp the bottle from above at its middle, lift it.
# 3. Place it into the footed bowl, release it, move up.
detect_objects(object_list=['white_medication_bottle', 'footed_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='white_medication_bottle', description='center'))
close_gripper()
attach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_medication_bottle', receptacle_name='footed_bowl'))
open_gripper()
detach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
