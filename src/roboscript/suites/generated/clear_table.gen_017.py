# Task: clear the table by putting every object lying on it into the basket; leave the baskets and bowls where they are
# Plan:
# 1. Pick up the brown box and put it into the basket.
# 2. Pick up the red block and put it into the basket.
# 3. Pick up the white and yellow mug and put it into the basket.
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


pick('brown_box')
put('brown_box', parse_place_pose(object_name='brown_box', receptacle_name='basket'))
pick('red_block')
put('red_block', parse_place_pose(object_name='red_block', receptacle_name='basket'))
pick('white_and_yellow_mug')
put('white_and_yellow_mug', parse_place_pose(object_name='white_and_yellow_mug', receptacle_name='basket'))
