# Task: swap the positions of the yellow mug and the sponge
# Plan:
# 1. Remember where the yellow mug and the sponge are now.
# 2. Put the yellow mug aside on the table, out of the way.
# 3. Put the sponge where the yellow mug was.
# 4. Put the yellow mug where the sponge was.
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


yellow_mug_position = get_object_center_position('yellow_mug')
sponge_position = get_object_center_position('sponge')
pick('yellow_mug')
put('yellow_mug', parse_place_pose(object_name='yellow_mug', receptacle_name='table'))
pick('sponge')
put('sponge', parse_place_pose(object_name='sponge', position=yellow_mug_position))
pick('yellow_mug')
put('yellow_mug', parse_place_pose(object_name='yellow_mug', position=sponge_position))
