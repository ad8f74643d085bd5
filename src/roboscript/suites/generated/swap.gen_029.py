# Task: swap the positions of the white medication bottle and the blue cup
# Plan:
# 1. Remember where the white medication bottle and the blue cup are now.
# 2. Put the white medication bottle aside on the table, out of the way.
# 3. Put the blue cup where the white medication bottle was.
# 4. Put the white medication bottle where the blue cup was.
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
blue_cup_position = get_object_center_position('blue_cup')
pick('white_medication_bottle')
put('white_medication_bottle', parse_place_pose(object_name='white_medication_bottle', receptacle_name='table'))
pick('blue_cup')
put('blue_cup', parse_place_pose(object_name='blue_cup', position=white_medication_bottle_position))
pick('white_medication_bottle')
put('white_medication_bottle', parse_place_pose(object_name='white_medication_bottle', position=blue_cup_position))
