# Task: place the brown cup into an empty plate.
# Plan:
# 1. Detect the objects and find the plates.
# 2. A plate is empty when no other object's centre lies over it; pick that plate.
# 3. Grasp the brown cup by its rim from above (it is as wide as the open gripper), attach it and lift it.
# 4. Place it on the empty plate and release it; move the gripper up.
detect_objects()
names = get_object_name_list()
plates = [name for name in names if 'plate' in name]
empty_plate = None
for plate in plates:
    bbox = get_3d_bbox(plate)
    occupied = False
    for other in names:
        if other in (plate, 'brown_cup', 'table', 'cabinet') or '.' in other:
            continue
        center = get_object_center_position(other)
        if bbox[0] < center[0] < bbox[3] and bbox[1] < center[1] < bbox[4]:
            occupied = True
    if not occupied:
        empty_plate = plate
        break
open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose(object_name='brown_cup', preferred_approach_direction=[0, 0, -1])
grasp(grasp_pose)
close_gripper()
attach_object('brown_cup')
move_in_direction(direction=[0, 0, 1], distance=0.1)
place_pose = parse_place_pose(object_name='brown_cup', receptacle_name=empty_plate)
move_to_pose(place_pose)
open_gripper()
detach_object('brown_cup')
move_in_direction(direction=[0, 0, 1], distance=0.1)
