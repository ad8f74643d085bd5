# Task: exchange the places of the green apple and the red box
# Plan:
# 1. Remember where the green apple and the red box are now.
# 2. Put the green apple aside on the table, out of the way.
# 3. Put the red box where the green apple was.
# 4. Put the green apple where the red box was.
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


green_apple_position = get_object_center_position('green_apple')
red_box_position = get_object_center_position('red_box')
pick('green_apple')
put('green_apple', parse_place_pose(object_name='green_apple', receptacle_name='table'))
pick('red_box')
put('red_box', parse_place_pose(object_name='red_box', position=green_apple_position))
pick('green_apple')
put('green_apple', parse_place_pose(object_name='green_apple', position=red_box_position))
