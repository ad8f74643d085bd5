# Task: place the brown cup into an empty plate; find the empty plate by checking
#       whether any object lies in the plate's 2D region on the table.
# Plan:
# 1. Detect all objects.
# 2. The plates are the names containing 'plate': white_ceramic_plate, turquoise_salad_plate.
# 3. For each plate, check whether the (x, y) centre of any other object (not the table or the cabinet)
#    falls inside the plate's 2D bounding box; a plate with none is empty.
# 4. Grasp the brown cup by its rim from above, lift it.
# 5. Place it onto the first empty plate, release it, move up.
detect_objects()
names = [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet')]
plates = [n for n in names if 'plate' in n]


def is_plate_empty(plate):
    bbox = get_3d_bbox(plate)
    for obj in names:
        if obj == plate:
            continue
        pos = get_object_center_position(obj)
        if bbox[0] <= pos[0] <= bbox[3] and bbox[1] <= pos[1] <= bbox[4]:
            return False
    return True


empty_plates = [p for p in plates if is_plate_empty(p)]
if not empty_plates:
    raise Exception('No empty plate found')
target_plate = empty_plates[0]

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('brown_ceramic_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('brown_ceramic_cup', target_plate))
open_gripper()
detach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
