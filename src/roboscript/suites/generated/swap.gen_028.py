# Task: swap the positions of the brown ceramic cup and the brown cup
# Plan:
# 1. Remember where the brown ceramic cup and the brown cup are now.
# 2. Put the brown ceramic cup aside on the table, out of the way.
# 3. Put the brown cup where the brown ceramic cup was.
# 4. Put the brown ceramic cup where the brown cup was.
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


brown_ceramic_cup_position = get_object_center_position('brown_ceramic_cup')
brown_cup_position = get_object_center_position('brown_cup')
pick('brown_ceramic_cup')
put('brown_ceramic_cup', parse_place_pose(object_name='brown_ceramic_cup', receptacle_name='table'))
pick('brown_cup')
put('brown_cup', parse_place_pose(object_name='brown_cup', position=brown_ceramic_cup_position))
pick('brown_ceramic_cup')
put('brown_ceramic_cup', parse_place_pose(object_name='brown_ceramic_cup', position=brown_cup_position))
