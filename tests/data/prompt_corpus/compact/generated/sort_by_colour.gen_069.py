# Task: sort the objects on the table by colour: put the white objects on the white plate
# Plan:
# 1. The white objects on the table (besides the white plate itself) are: white_medication_bottle.
# 2. Grasp the bottle from above at its middle, lift it.
# 3. Place it onto the white plate, release it, move up.
detect_objects(object_list=['white_medication_bottle', 'white_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='white_medication_bottle', description='center'))
close_gripper()
attach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_medication_bottle', receptacle_name='white_plate'))
open_gripper()
detach_object('white_medication_bottle')
move_in_direction([0, 0, 1], 0.1)
