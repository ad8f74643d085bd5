# Task: exchange the places of the gelatin box and the red mug
# Plan:
# 1. Remember where the gelatin box and the red mug are now.
# 2. Put the gelatin box aside on the table, out of the way.
# 3. Put the red mug where the gelatin box was.
# 4. Put the gelatin box where the red mug was.
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
red_mug_position = get_object_center_position('red_mug')
pick('gelatin_box')
put('gelatin_box', parse_place_pose(object_name='gelatin_box', receptacle_name='table'))
pick('red_mug')
put('red_mug', parse_place_pose(object_name='red_mug', position=gelatin_box_position))
pick('gelatin_box')
put('gelatin_box', parse_place_pose(object_name='gelatin_box', position=red_mug_position))
