# Task: swap the positions of the green mug and the toy car
# Plan:
# 1. Remember where the green mug and the toy car are now.
# 2. Put the green mug aside on the table, out of the way.
# 3. Put the toy car where the green mug was.
# 4. Put the green mug where the toy car was.
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


green_mug_position = get_object_center_position('green_mug')
toy_car_position = get_object_center_position('toy_car')
pick('green_mug')
put('green_mug', parse_place_pose(object_name='green_mug', receptacle_name='table'))
pick('toy_car')
put('toy_car', parse_place_pose(object_name='toy_car', position=green_mug_position))
pick('green_mug')
put('green_mug', parse_place_pose(object_name='green_mug', position=toy_car_position))
