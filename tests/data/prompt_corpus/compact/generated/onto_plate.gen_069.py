# Task: place the toy car onto the white plate
# Plan:
# 1. Detect the toy car and the white plate.
# 2. Grasp the toy car from above, across its narrow side, lift it.
# 3. Place it onto the white plate, release it, move up.
detect_objects(object_list=['toy_car', 'white_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='toy_car', description='center'))
close_gripper()
attach_object('toy_car')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='toy_car', receptacle_name='white_plate'))
open_gripper()
detach_object('toy_car')
move_in_direction([0, 0, 1], 0.1)
