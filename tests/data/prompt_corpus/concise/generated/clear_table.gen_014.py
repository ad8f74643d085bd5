# Task: clear the table by putting every object lying on it into the basket; leave the basket, bowl and plate.
# Plan:
# 1. The objects to move are the yellow box, the tea box and the green block.
# 2. For each: grasp it from above, lift it, place it into the basket, release it, move up.
detect_objects()
for name in ['yellow_box', 'tea_box', 'green_block']:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
