# Task: exchange the places of the white medication bottle and the apple
# Plan:
# 1. Remember where the white medication bottle and the apple are now.
# 2. Put the white medication bottle aside on the table, out of the way.
# 3. Put the apple where the white medication bottle was.
# 4. Put the white medication bottle where the apple was.
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


white_medication_bottle_position = get_object_center_position('white_medication_bottle')
apple_position = get_object_center_position('apple')
pick('white_medication_bottle')
put('white_medication_bottle', parse_place_pose(object_name='white_medication_bottle', receptacle_name='table'))
pick('apple')
put('apple', parse_place_pose(object_name='apple', position=white_medication_bottle_position))
pick('white_medication_bottle')
put('white_medication_bottle', parse_place_pose(object_name='white_medication_bottle', position=apple_position))
