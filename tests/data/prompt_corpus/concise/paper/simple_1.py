# Task: place the brown cup onto an empty plate: a plate whose 2D region on the table holds no other object.
# Plan:
# 1. For each plate, check whether the centre (x, y) of the lemon or the cup lies inside the plate's box in x, y.
# 2. Take the first plate with none inside as the empty plate.
# 3. Grasp the brown cup by its rim from above, lift it, place it onto the empty plate, release it, move up.
detect_objects()
centers = [get_object_center_position(name) for name in ['lemon', 'brown_ceramic_cup']]
for plate in ['white_ceramic_plate', 'turquoise_salad_plate']:
    b = get_3d_bbox(plate)
    if not any(b[0] <= c[0] <= b[3] and b[1] <= c[1] <= b[4] for c in centers):
        empty_plate = plate
        break
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='brown_ceramic_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='brown_ceramic_cup', receptacle_name=empty_plate))
open_gripper()
detach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
