# Task: exchange the places of the brown mug and the toy bus
# Plan:
# 1. Remember where the brown mug and the toy bus are now.
# 2. Put the brown mug aside on the table, out of the way.
# 3. Put the toy bus where the brown mug was.
# 4. Put the brown mug where the toy bus was.
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


brown_mug_position = get_object_center_position('brown_mug')
toy_bus_position = get_object_center_position('toy_bus')
pick('brown_mug')
put('brown_mug', parse_place_pose(object_name='brown_mug', receptacle_name='table'))
pick('toy_bus')
put('toy_bus', parse_place_pose(object_name='toy_bus', position=brown_mug_position))
pick('brown_mug')
put('brown_mug', parse_place_pose(object_name='brown_mug', position=toy_bus_position))
