# Task: exchange the places of the green cup and the toy car
# Plan:
# 1. Remember where the green cup and the toy car are now.
# 2. Put the green cup aside on the table, out of the way.
# 3. Put the toy car where the green cup was.
# 4. Put the green cup where the toy car was.
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


green_cup_position = get_object_center_position('green_cup')
toy_car_position = get_object_center_position('toy_car')
pick('green_cup')
put('green_cup', parse_place_pose(object_name='green_cup', receptacle_name='table'))
pick('toy_car')
put('toy_car', parse_place_pose(object_name='toy_car', position=green_cup_position))
pick('green_cup')
put('green_cup', parse_place_pose(object_name='green_cup', position=toy_car_position))
