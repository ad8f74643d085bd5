# Task: swap the positions of the pear and the medication bottle
# Plan:
# 1. Remember where the pear and the medication bottle are now.
# 2. Put the pear aside on the table, out of the way.
# 3. Put the medication bottle where the pear was.
# 4. Put the pear where the medication bottle was.
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
medication_bottle_position = get_object_center_position('medication_bottle')
pick('pear')
put('pear', parse_place_pose(object_name='pear', receptacle_name='table'))
pick('medication_bottle')
put('medication_bottle', parse_place_pose(object_name='medication_bottle', position=pear_position))
pick('pear')
put('pear', parse_place_pose(object_name='pear', position=medication_bottle_position))
