# Task: swap the positions of the green block and the lemon
# Plan:
# 1. Remember where the green block and the lemon are now.
# 2. Put the green block aside on the table, out of the way.
# 3. Put the lemon where the green block was.
# 4. Put the green block where the lemon was.
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


green_block_position = get_object_center_position('green_block')
lemon_position = get_object_center_position('lemon')
pick('green_block')
put('green_block', parse_place_pose(object_name='green_block', receptacle_name='table'))
pick('lemon')
put('lemon', parse_place_pose(object_name='lemon', position=green_block_position))
pick('green_block')
put('green_block', parse_place_pose(object_name='green_block', position=lemon_position))
