# Task: sort the objects on the table by colour: put the blue objects on the blue plate
# Plan:
# 1. The blue objects besides the plate itself: the blue saucer and the blue cup.
# 2. The saucer first (flat, wider than the gripper: adaptive grasp), then the cup (adaptive grasp from above).
# 3. For each: grasp, lift, place onto the blue plate, release, move up.
detect_objects()
for name in ['blue_saucer', 'blue_cup']:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='blue_plate'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
