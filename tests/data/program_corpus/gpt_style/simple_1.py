# Step 1: find the empty plate: a plate is empty if no other object's center lies in its 2D region
plates = ['white_ceramic_plate', 'turquoise_salad_plate']
others = ['lemon']
empty_plate = None
for plate in plates:
    bbox = get_3d_bbox(plate)
    is_empty = True
    for obj in others:
        center = get_object_center_position(obj)
        if bbox[0] <= center[0] <= bbox[3] and bbox[1] <= center[1] <= bbox[4]:
            is_empty = False
    if is_empty:
        empty_plate = plate
        break

# Step 2: grasp the brown cup
open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('brown_ceramic_cup')
grasp(grasp_pose)
close_gripper()
attach_object('brown_ceramic_cup')

# Step 3: place it into the empty plate
place_pose = parse_place_pose('brown_ceramic_cup', empty_plate)
move_to_pose(place_pose)
open_gripper()
detach_object('brown_ceramic_cup')
