# Task: swap the positions of the red block and the lime
# Plan:
# 1. Remember where the red block and the lime are now.
# 2. Put the red block aside on the table, out of the way.
# 3. Put the lime where the red block was.
# 4. Put the red block where the lime was.
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


red_block_position = get_object_center_position('red_block')
lime_position = get_object_center_position('lime')
pick('red_block')
put('red_block', parse_place_pose(object_name='red_block', receptacle_name='table'))
pick('lime')
put('lime', parse_place_pose(object_name='lime', position=red_block_position))
pick('red_block')
put('red_block', parse_place_pose(object_name='red_block', position=lime_position))
