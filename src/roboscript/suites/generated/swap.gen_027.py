# Task: exchange the places of the green cup and the wooden block
# Plan:
# 1. Remember where the green cup and the wooden block are now.
# 2. Put the green cup aside on the table, out of the way.
# 3. Put the wooden block where the green cup was.
# 4. Put the green cup where the wooden block was.
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


green_cup_position = get_object_center_position('green_cup')
wooden_block_position = get_object_center_position('wooden_block')
pick('green_cup')
put('green_cup', parse_place_pose(object_name='green_cup', receptacle_name='table'))
pick('wooden_block')
put('wooden_block', parse_place_pose(object_name='wooden_block', position=green_cup_position))
pick('green_cup')
put('green_cup', parse_place_pose(object_name='green_cup', position=wooden_block_position))
