# Task: swap the positions of the brown ceramic cup and the toy car
# Plan:
# 1. Remember where the brown ceramic cup and the toy car are now.
# 2. Put the brown ceramic cup aside on the table, out of the way.
# 3. Put the toy car where the brown ceramic cup was.
# 4. Put the brown ceramic cup where the toy car was.
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
toy_car_position = get_object_center_position('toy_car')
pick('brown_ceramic_cup')
put('brown_ceramic_cup', parse_place_pose(object_name='brown_ceramic_cup', receptacle_name='table'))
pick('toy_car')
put('toy_car', parse_place_pose(object_name='toy_car', position=brown_ceramic_cup_position))
pick('brown_ceramic_cup')
put('brown_ceramic_cup', parse_place_pose(object_name='brown_ceramic_cup', position=toy_car_position))
