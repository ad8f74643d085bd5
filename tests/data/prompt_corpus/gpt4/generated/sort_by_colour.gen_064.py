# Task: sort the objects on the table by colour: put the green objects into the green bowl.
# Plan:
# 1. Detect the objects.
# 2. Decide which objects are green from their names: green_block (green_bowl is the container itself
#    and stays where it is; the other objects are not green).
# 3. For each green object: grasp it with the adaptive grasp from above, lift it, place it into the
#    green bowl, release it and move up.


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
green_objects = ['green_block']
for object_name in green_objects:
    pick_and_place(object_name, 'green_bowl')
