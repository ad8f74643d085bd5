# Task: swap the positions of the red block and the white medication bottle
# Plan:
# 1. Remember where the red block and the white medication bottle are now.
# 2. Put the red block aside on the table, out of the way.
# 3. Put the white medication bottle where the red block was.
# 4. Put the red block where the white medication bottle was.
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
white_medication_bottle_position = get_object_center_position('white_medication_bottle')
pick('red_block')
put('red_block', parse_place_pose(object_name='red_block', receptacle_name='table'))
pick('white_medication_bottle')
put('white_medication_bottle', parse_place_pose(object_name='white_medication_bottle', position=red_block_position))
pick('red_block')
put('red_block', parse_place_pose(object_name='red_block', position=white_medication_bottle_position))
