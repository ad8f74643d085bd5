# Task: sort the objects on the table by colour: put the blue objects on the blue plate.
# Plan:
# 1. The blue objects other than the blue plate itself are the blue saucer and the blue cup
#    (the medication bottle and the green apple are not blue).
# 2. Move the flat saucer first, then the cup, so the cup does not stand in the saucer's way.
# 3. For each: grasp it from above with an adaptive grasp, lift it, place it on the blue plate,
#    release it and move up.
detect_objects()
blue_objects = ['blue_saucer', 'blue_cup']


def pick_and_place(name, receptacle):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(name, preferred_approach_direction=np.array([0, 0, -1])))
    close_gripper()
    attach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)
    move_to_pose(parse_place_pose(name, receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction(np.array([0, 0, 1]), 0.1)


for name in blue_objects:
    pick_and_place(name, 'blue_plate')
