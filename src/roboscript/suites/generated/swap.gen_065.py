# Task: swap the positions of the red cup and the brown mug
# Plan:
# 1. Remember where the red cup and the brown mug are now.
# 2. Put the red cup aside on the table, out of the way.
# 3. Put the brown mug where the red cup was.
# 4. Put the red cup where the brown mug was.
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


red_cup_position = get_object_center_position('red_cup')
brown_mug_position = get_object_center_position('brown_mug')
pick('red_cup')
put('red_cup', parse_place_pose(object_name='red_cup', receptacle_name='table'))
pick('brown_mug')
put('brown_mug', parse_place_pose(object_name='brown_mug', position=red_cup_position))
pick('red_cup')
put('red_cup', parse_place_pose(object_name='red_cup', position=brown_mug_position))
