# Task: exchange the places of the red box and the red cup
# Plan:
# 1. Remember where the red box and the red cup are now.
# 2. Put the red box aside on the table, out of the way.
# 3. Put the red cup where the red box was.
# 4. Put the red box where the red cup was.
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


red_box_position = get_object_center_position('red_box')
red_cup_position = get_object_center_position('red_cup')
pick('red_box')
put('red_box', parse_place_pose(object_name='red_box', receptacle_name='table'))
pick('red_cup')
put('red_cup', parse_place_pose(object_name='red_cup', position=red_box_position))
pick('red_box')
put('red_box', parse_place_pose(object_name='red_box', position=red_cup_position))
