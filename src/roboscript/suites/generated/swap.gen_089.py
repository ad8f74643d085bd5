# Task: swap the positions of the soup can and the peach
# Plan:
# 1. Remember where the soup can and the peach are now.
# 2. Put the soup can aside on the table, out of the way.
# 3. Put the peach where the soup can was.
# 4. Put the soup can where the peach was.
detect_objects()


def pick(name):
    """Grasps `name` from above where its shape allows, and lifts it clear of what is around it."""
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


def put(name, place_pose):
    """Carries the held `name` to `place_pose`, lets go of it and moves the hand up and away."""
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


soup_can_position = get_object_center_position('soup_can')
peach_position = get_object_center_position('peach')
pick('soup_can')
put('soup_can', parse_place_pose(object_name='soup_can', receptacle_name='table'))
pick('peach')
put('peach', parse_place_pose(object_name='peach', position=soup_can_position))
pick('soup_can')
put('soup_can', parse_place_pose(object_name='soup_can', position=peach_position))
