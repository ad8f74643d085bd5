# Task: sort the objects on the table by colour: put the green objects into the green bowl.
# Plan:
# 1. Detect all objects.
# 2. The green objects are those whose name starts with 'green' (the bowl itself excluded): green_block.
# 3. For each green object: grasp it, lift it, place it into the green bowl, release, move up.
detect_objects()
green_objects = [name for name in get_object_name_list()
                 if name.startswith('green_') and name != 'green_bowl']

for obj in green_objects:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, 'green_bowl'))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
