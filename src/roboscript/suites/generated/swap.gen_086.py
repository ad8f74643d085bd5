# Task: swap the positions of the gelatin box and the golf ball
# Plan:
# 1. Remember where the gelatin box and the golf ball are now.
# 2. Put the gelatin box aside on the table, out of the way.
# 3. Put the golf ball where the gelatin box was.
# 4. Put the gelatin box where the golf ball was.
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


gelatin_box_position = get_object_center_position('gelatin_box')
golf_ball_position = get_object_center_position('golf_ball')
pick('gelatin_box')
put('gelatin_box', parse_place_pose(object_name='gelatin_box', receptacle_name='table'))
pick('golf_ball')
put('golf_ball', parse_place_pose(object_name='golf_ball', position=gelatin_box_position))
pick('gelatin_box')
put('gelatin_box', parse_place_pose(object_name='gelatin_box', position=golf_ball_position))
