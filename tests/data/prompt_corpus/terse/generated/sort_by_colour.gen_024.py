# Task: sort the objects on the table by colour: put the red objects on the red plate.
# Plan:
# 1. Detect everything. Colours come only from names: the red objects other than the plate are those named red_*,
#    here only red_cup ('apple' names no colour, so it stays).
# 2. Grasp each with the adaptive grasp from above (a cup may be wider than the opening), close, attach, lift.
# 3. Place it on the red plate, release it and move up.
detect_objects()
for n in [n for n in get_object_name_list() if n.startswith('red_') and n != 'red_plate']:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(n, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(n)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(n, 'red_plate'))
    open_gripper()
    detach_object(n)
    move_in_direction([0, 0, 1], 0.1)
