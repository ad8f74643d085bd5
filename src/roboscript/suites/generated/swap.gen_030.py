# Task: exchange the places of the tea box and the lemon
# Plan:
# 1. Remember where the tea box and the lemon are now.
# 2. Put the tea box aside on the table, out of the way.
# 3. Put the lemon where the tea box was.
# 4. Put the tea box where the lemon was.
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


tea_box_position = get_object_center_position('tea_box')
lemon_position = get_object_center_position('lemon')
pick('tea_box')
put('tea_box', parse_place_pose(object_name='tea_box', receptacle_name='table'))
pick('lemon')
put('lemon', parse_place_pose(object_name='lemon', position=tea_box_position))
pick('tea_box')
put('tea_box', parse_place_pose(object_name='tea_box', position=lemon_position))
