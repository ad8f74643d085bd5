# Task: place all fruits on the table into the white plate.
# Plan:
# 1. The fruits are the apple and the banana.
# 2. For each: grasp it from above, lift it, place it onto the white ceramic plate, release it, move up.
detect_objects()
for name in ['apple', 'banana']:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='white_ceramic_plate'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
