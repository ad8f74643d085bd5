# Task: exchange the places of the baseball and the blue box
# Plan:
# 1. Remember where the baseball and the blue box are now.
# 2. Put the baseball aside on the table, out of the way.
# 3. Put the blue box where the baseball was.
# 4. Put the baseball where the blue box was.
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


baseball_position = get_object_center_position('baseball')
blue_box_position = get_object_center_position('blue_box')
pick('baseball')
put('baseball', parse_place_pose(object_name='baseball', receptacle_name='table'))
pick('blue_box')
put('blue_box', parse_place_pose(object_name='blue_box', position=baseball_position))
pick('baseball')
put('baseball', parse_place_pose(object_name='baseball', position=blue_box_position))
