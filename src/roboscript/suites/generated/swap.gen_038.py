# Task: exchange the places of the brown box and the pear
# Plan:
# 1. Remember where the brown box and the pear are now.
# 2. Put the brown box aside on the table, out of the way.
# 3. Put the pear where the brown box was.
# 4. Put the brown box where the pear was.
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


brown_box_position = get_object_center_position('brown_box')
pear_position = get_object_center_position('pear')
pick('brown_box')
put('brown_box', parse_place_pose(object_name='brown_box', receptacle_name='table'))
pick('pear')
put('pear', parse_place_pose(object_name='pear', position=brown_box_position))
pick('brown_box')
put('brown_box', parse_place_pose(object_name='brown_box', position=pear_position))
