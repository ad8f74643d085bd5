# Task: swap the positions of the pear and the blue block
# Plan:
# 1. Remember where the pear and the blue block are now.
# 2. Put the pear aside on the table, out of the way.
# 3. Put the blue block where the pear was.
# 4. Put the pear where the blue block was.
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


pear_position = get_object_center_position('pear')
blue_block_position = get_object_center_position('blue_block')
pick('pear')
put('pear', parse_place_pose(object_name='pear', receptacle_name='table'))
pick('blue_block')
put('blue_block', parse_place_pose(object_name='blue_block', position=pear_position))
pick('pear')
put('pear', parse_place_pose(object_name='pear', position=blue_block_position))
