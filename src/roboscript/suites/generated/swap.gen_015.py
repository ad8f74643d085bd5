# Task: exchange the places of the wooden bar and the yellow mug
# Plan:
# 1. Remember where the wooden bar and the yellow mug are now.
# 2. Put the wooden bar aside on the table, out of the way.
# 3. Put the yellow mug where the wooden bar was.
# 4. Put the wooden bar where the yellow mug was.
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


wooden_bar_position = get_object_center_position('wooden_bar')
yellow_mug_position = get_object_center_position('yellow_mug')
pick('wooden_bar')
put('wooden_bar', parse_place_pose(object_name='wooden_bar', receptacle_name='table'))
pick('yellow_mug')
put('yellow_mug', parse_place_pose(object_name='yellow_mug', position=wooden_bar_position))
pick('wooden_bar')
put('wooden_bar', parse_place_pose(object_name='wooden_bar', position=yellow_mug_position))
