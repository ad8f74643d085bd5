# Task: exchange the places of the rubiks cube and the plum
# Plan:
# 1. Remember where the rubiks cube and the plum are now.
# 2. Put the rubiks cube aside on the table, out of the way.
# 3. Put the plum where the rubiks cube was.
# 4. Put the rubiks cube where the plum was.
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


rubiks_cube_position = get_object_center_position('rubiks_cube')
plum_position = get_object_center_position('plum')
pick('rubiks_cube')
put('rubiks_cube', parse_place_pose(object_name='rubiks_cube', receptacle_name='table'))
pick('plum')
put('plum', parse_place_pose(object_name='plum', position=rubiks_cube_position))
pick('rubiks_cube')
put('rubiks_cube', parse_place_pose(object_name='rubiks_cube', position=plum_position))
