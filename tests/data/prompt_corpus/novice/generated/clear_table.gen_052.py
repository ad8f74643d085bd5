# Task: clear the table by putting every object lying on it into the basket; leave the baskets and plates where they are.
# Plan:
# 1. The objects to move are gelatin_box, red_mug, toy_car and apple (not the table, the basket or the red plate).
# 2. For each one: grasp it (the mug by the adaptive grasp from above, the others from above at their middle),
#    lift it, place it into the basket, release it, move up.
detect_objects()
objects_to_move = ['gelatin_box', 'red_mug', 'toy_car', 'apple']
for name in objects_to_move:
    open_gripper()
    if name == 'red_mug':
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
