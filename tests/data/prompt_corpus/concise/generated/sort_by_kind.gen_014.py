# Task: sort the objects on the table by kind: put the boxes into the basket.
# Plan:
# 1. The boxes are the yellow box and the tea box.
# 2. For each: grasp it from above, lift it, place it into the basket, release it, move up.
detect_objects()
for name in ['yellow_box', 'tea_box']:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
