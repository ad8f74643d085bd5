# Task: swap the positions of the brown cup and the lemon
# Plan:
# 1. Remember where the brown cup and the lemon are now.
# 2. Put the brown cup aside on the table, out of the way.
# 3. Put the lemon where the brown cup was.
# 4. Put the brown cup where the lemon was.
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


brown_cup_position = get_object_center_position('brown_cup')
lemon_position = get_object_center_position('lemon')
pick('brown_cup')
put('brown_cup', parse_place_pose(object_name='brown_cup', receptacle_name='table'))
pick('lemon')
put('lemon', parse_place_pose(object_name='lemon', position=brown_cup_position))
pick('brown_cup')
put('brown_cup', parse_place_pose(object_name='brown_cup', position=lemon_position))
