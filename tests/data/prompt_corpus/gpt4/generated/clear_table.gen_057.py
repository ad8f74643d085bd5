# Task: clear the table by putting every object lying on it into the basket;
#       leave the baskets and plates and saucers where they are.
# Plan:
# 1. Detect all objects.
# 2. Objects to move (from their names): green_mug, red_box, gelatin_box, red_block, red_cup.
#    The basket, the red plate and the blue saucer stay where they are.
# 3. For each object: grasp it, lift it, place it into the basket, release it, move up.
detect_objects()

objects_to_move = ['green_mug', 'red_box', 'gelatin_box', 'red_block', 'red_cup']

for obj in objects_to_move:
    open_gripper()
    if 'mug' in obj or 'cup' in obj:
        # mugs and cups: grasp by the rim from above
        grasp_pose = parse_adaptive_shape_grasp_pose(obj, preferred_approach_direction=[0, 0, -1])
    else:
        grasp_pose = parse_adaptive_shape_grasp_pose(obj)
    grasp(grasp_pose)
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    place_pose = parse_place_pose(obj, 'basket')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
