# Task: clear the table by putting every object lying on it into the basket; leave the baskets, bowls and plates where they are.
# Plan:
# 1. Detect everything. The things to move are white_mug, blue_block and golf_ball (basket, green_plate, white_bowl stay).
# 2. For each, biggest first: open the gripper and grasp it (the mug with the adaptive grasp from above, by its rim,
#    as a mug may be wider than the opening; the block and the ball from above at their middle).
# 3. Close, attach, lift, place it into the basket, release it and move up.
detect_objects()
for n in ['white_mug', 'blue_block', 'golf_ball']:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(n, preferred_approach_direction=[0, 0, -1]) if 'mug' in n else parse_central_lift_grasp_pose(n, 'center'))
    close_gripper()
    attach_object(n)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(n, 'basket'))
    open_gripper()
    detach_object(n)
    move_in_direction([0, 0, 1], 0.1)
