# Task: swap the positions of the peach and the green cup
# Plan:
# 1. Remember where the peach and the green cup are now.
# 2. Put the peach aside on the table, out of the way.
# 3. Put the green cup where the peach was.
# 4. Put the peach where the green cup was.
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


peach_position = get_object_center_position('peach')
green_cup_position = get_object_center_position('green_cup')
pick('peach')
put('peach', parse_place_pose(object_name='peach', receptacle_name='table'))
pick('green_cup')
put('green_cup', parse_place_pose(object_name='green_cup', position=peach_position))
pick('peach')
put('peach', parse_place_pose(object_name='peach', position=green_cup_position))
