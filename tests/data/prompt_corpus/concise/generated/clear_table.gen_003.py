# Task: clear the table by putting every object lying on it into the basket; leave the basket, bowl and plate.
# Plan:
# 1. The objects to move are the golf ball, the white mug and the blue block.
# 2. For each: grasp it (the mug by its rim from above, the others from above at the middle), lift it.
# 3. Place it into the basket, release it, move up.
detect_objects()
for name in ['golf_ball', 'white_mug', 'blue_block']:
    open_gripper()
    if name == 'white_mug':
        grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    else:
        grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
