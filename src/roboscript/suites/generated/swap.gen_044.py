# Task: exchange the places of the blue box and the soup can
# Plan:
# 1. Remember where the blue box and the soup can are now.
# 2. Put the blue box aside on the table, out of the way.
# 3. Put the soup can where the blue box was.
# 4. Put the blue box where the soup can was.
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


blue_box_position = get_object_center_position('blue_box')
soup_can_position = get_object_center_position('soup_can')
pick('blue_box')
put('blue_box', parse_place_pose(object_name='blue_box', receptacle_name='table'))
pick('soup_can')
put('soup_can', parse_place_pose(object_name='soup_can', position=blue_box_position))
pick('blue_box')
put('blue_box', parse_place_pose(object_name='blue_box', position=soup_can_position))
