# Task: sort the objects on the table by colour: put the blue objects on the blue plate.
# Plan:
# 1. Detect the objects.
# 2. Decide which objects are blue from their names: blue_cup is moved; blue_plate is the target
#    and blue_saucer is a saucer, which stays where it is; the others are not blue.
# 3. For each blue object: grasp it with the adaptive grasp from above, lift it, place it on the
#    blue plate, release it and move up.


def pick_and_place(object_name, receptacle_name):
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name, None, np.array([0, 0, -1]))
    grasp(grasp_pose)
    close_gripper()
    attach_object(object_name)
    move_in_direction(np.array([0, 0, 1]), 0.1)
    place_pose = parse_place_pose(object_name, receptacle_name)
    move_to_pose(place_pose)
    open_gripper()
    detach_object(object_name)
    move_in_direction(np.array([0, 0, 1]), 0.1)


detect_objects()
blue_objects = ['blue_cup']
for object_name in blue_objects:
    pick_and_place(object_name, 'blue_plate')
