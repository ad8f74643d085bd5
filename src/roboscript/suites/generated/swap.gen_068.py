# Task: exchange the places of the toy car and the red mug
# Plan:
# 1. Remember where the toy car and the red mug are now.
# 2. Put the toy car aside on the table, out of the way.
# 3. Put the red mug where the toy car was.
# 4. Put the toy car where the red mug was.
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


toy_car_position = get_object_center_position('toy_car')
red_mug_position = get_object_center_position('red_mug')
pick('toy_car')
put('toy_car', parse_place_pose(object_name='toy_car', receptacle_name='table'))
pick('red_mug')
put('red_mug', parse_place_pose(object_name='red_mug', position=toy_car_position))
pick('toy_car')
put('toy_car', parse_place_pose(object_name='toy_car', position=red_mug_position))
