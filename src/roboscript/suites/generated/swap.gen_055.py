# Task: swap the positions of the lime and the plum
# Plan:
# 1. Remember where the lime and the plum are now.
# 2. Put the lime aside on the table, out of the way.
# 3. Put the plum where the lime was.
# 4. Put the lime where the plum was.
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


lime_position = get_object_center_position('lime')
plum_position = get_object_center_position('plum')
pick('lime')
put('lime', parse_place_pose(object_name='lime', receptacle_name='table'))
pick('plum')
put('plum', parse_place_pose(object_name='plum', position=lime_position))
pick('lime')
put('lime', parse_place_pose(object_name='lime', position=plum_position))
