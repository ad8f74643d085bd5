# Task: swap the positions of the blue cup and the blue box
# Plan:
# 1. Remember where the blue cup and the blue box are now.
# 2. Put the blue cup aside on the table, out of the way.
# 3. Put the blue box where the blue cup was.
# 4. Put the blue cup where the blue box was.
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


blue_cup_position = get_object_center_position('blue_cup')
blue_box_position = get_object_center_position('blue_box')
pick('blue_cup')
put('blue_cup', parse_place_pose(object_name='blue_cup', receptacle_name='table'))
pick('blue_box')
put('blue_box', parse_place_pose(object_name='blue_box', position=blue_cup_position))
pick('blue_cup')
put('blue_cup', parse_place_pose(object_name='blue_cup', position=blue_box_position))
