# Task: exchange the places of the banana and the red mug
# Plan:
# 1. Remember where the banana and the red mug are now.
# 2. Put the banana aside on the table, out of the way.
# 3. Put the red mug where the banana was.
# 4. Put the banana where the red mug was.
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


banana_position = get_object_center_position('banana')
red_mug_position = get_object_center_position('red_mug')
pick('banana')
put('banana', parse_place_pose(object_name='banana', receptacle_name='table'))
pick('red_mug')
put('red_mug', parse_place_pose(object_name='red_mug', position=banana_position))
pick('banana')
put('banana', parse_place_pose(object_name='banana', position=red_mug_position))
