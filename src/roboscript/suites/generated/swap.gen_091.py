# Task: exchange the places of the green mug and the blue mug
# Plan:
# 1. Remember where the green mug and the blue mug are now.
# 2. Put the green mug aside on the table, out of the way.
# 3. Put the blue mug where the green mug was.
# 4. Put the green mug where the blue mug was.
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


green_mug_position = get_object_center_position('green_mug')
blue_mug_position = get_object_center_position('blue_mug')
pick('green_mug')
put('green_mug', parse_place_pose(object_name='green_mug', receptacle_name='table'))
pick('blue_mug')
put('blue_mug', parse_place_pose(object_name='blue_mug', position=green_mug_position))
pick('green_mug')
put('green_mug', parse_place_pose(object_name='green_mug', position=blue_mug_position))
