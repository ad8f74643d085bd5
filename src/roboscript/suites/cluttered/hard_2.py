# Task: clear the table by moving all table objects into the basket.
# Plan:
# 1. Detect the objects; everything on the table except the basket has to go (the table itself is listed too).
# 2. For each object: grasp it from above, lift it, place it into the basket, release it and move up.
detect_objects()
objects = [name for name in get_object_name_list() if name not in ('table', 'basket')]
for name in objects:
    open_gripper()
    grasp_pose = parse_central_lift_grasp_pose(object_name=name, description='top')
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.12)
    place_pose = parse_place_pose(object_name=name, receptacle_name='basket')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
