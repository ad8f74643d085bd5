# Task: swap the positions of the white and pink box and the green apple
# Plan:
# 1. Remember where the white and pink box and the green apple are now.
# 2. Put the white and pink box aside on the table, out of the way.
# 3. Put the green apple where the white and pink box was.
# 4. Put the white and pink box where the green apple was.
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


white_and_pink_box_position = get_object_center_position('white_and_pink_box')
green_apple_position = get_object_center_position('green_apple')
pick('white_and_pink_box')
put('white_and_pink_box', parse_place_pose(object_name='white_and_pink_box', receptacle_name='table'))
pick('green_apple')
put('green_apple', parse_place_pose(object_name='green_apple', position=white_and_pink_box_position))
pick('white_and_pink_box')
put('white_and_pink_box', parse_place_pose(object_name='white_and_pink_box', position=green_apple_position))
