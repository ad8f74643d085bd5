# Task: clear the table by moving all table objects into the basket.
# Plan:
# 1. The objects on the table (other than the basket) are the orange and the toy bus.
# 2. For each: grasp it from above, lift it, place it into the basket, release it, move up.
detect_objects()
for name in ['orange', 'toy_bus']:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket_with_fabric_liner'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
