# Task: sort the objects on the table by colour: put the white objects on the white plate.
# Plan:
# 1. Detect all objects.
# 2. The white objects are those with 'white' in the name, except the white plate: white_medication_bottle.
# 3. For each white object: grasp it, lift it, place it on the white plate, release, move up.
detect_objects()
white_objects = [name for name in get_object_name_list()
                 if 'white' in name.split('_') and name != 'white_plate']


def pick_and_place(obj, receptacle):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, receptacle))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


for obj in white_objects:
    pick_and_place(obj, 'white_plate')
