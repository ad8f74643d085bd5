# Task: exchange the places of the lemon and the blue cup
# Plan:
# 1. Remember where the lemon and the blue cup are now.
# 2. Put the lemon aside on the table, out of the way.
# 3. Put the blue cup where the lemon was.
# 4. Put the lemon where the blue cup was.
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


lemon_position = get_object_center_position('lemon')
blue_cup_position = get_object_center_position('blue_cup')
pick('lemon')
put('lemon', parse_place_pose(object_name='lemon', receptacle_name='table'))
pick('blue_cup')
put('blue_cup', parse_place_pose(object_name='blue_cup', position=lemon_position))
pick('lemon')
put('lemon', parse_place_pose(object_name='lemon', position=blue_cup_position))
