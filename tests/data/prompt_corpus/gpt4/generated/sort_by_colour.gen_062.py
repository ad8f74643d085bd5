# Task: sort the objects on the table by colour: put the blue objects on the blue plate.
# Plan:
# 1. The blue objects are those whose names say 'blue', other than the blue plate itself, the table and
#    the cabinet with its parts: here only the blue block (the plum, green bowl, green mug and brown cup are not blue).
# 2. For each blue object: grasp it from above with an adaptive grasp, lift it, place it on the blue plate,
#    release it and move up.
detect_objects()
blue_objects = [name for name in get_object_name_list()
                if 'blue' in name.split('_') and name != 'blue_plate'
                and name != 'table' and not name.startswith('cabinet')]


def pick_and_place(name, receptacle):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(name, preferred_approach_direction=np.array([0, 0, -1])))
    close_gripper()
    attach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)
    move_to_pose(parse_place_pose(name, receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)


for name in blue_objects:
    pick_and_place(name, 'blue_plate')
