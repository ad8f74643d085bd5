# Task: place the brown cup onto an empty plate; a plate is empty when no object lies in its 2D region on the table.
# Plan:
# 1. Detect everything. The plates are white_ceramic_plate and turquoise_salad_plate.
# 2. For each plate, take its box's x, y extent as its 2D region and check whether the centre (x, y) of any other
#    object on the table (not the table, the cabinet or its parts, not the plates) lies inside it.
# 3. Choose the first plate with nothing in it; the target is the middle of its box.
# 4. Grasp the brown cup by its rim from above with the adaptive grasp, attach it, lift it (a Pose from the
#    gripper's).
# 5. Place it on the empty plate at the target, release it, move up.
detect_objects()
plates = ['white_ceramic_plate', 'turquoise_salad_plate']
others = [name for name in get_object_name_list()
          if name != 'table' and name != 'cabinet' and not name.startswith('cabinet.') and name not in plates]


def plate_is_empty(plate):
    box = get_3d_bbox(plate)
    for name in others:
        c = get_object_center_position(name)
        if box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4]:
            return False
    return True


empty_plate = None
for plate in plates:
    if plate_is_empty(plate):
        empty_plate = plate
        break
if empty_plate is None:
    raise RuntimeError('no empty plate: every plate has an object in its 2D region')

plate_box = get_3d_bbox(empty_plate)
target = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='brown_ceramic_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('brown_ceramic_cup')
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='brown_ceramic_cup', receptacle_name=empty_plate, position=target))
open_gripper()
detach_object('brown_ceramic_cup')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
