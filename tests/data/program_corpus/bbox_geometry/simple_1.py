# The empty plate is the one whose box holds no other object's box centre.
detect_objects()
plates = ['white_ceramic_plate', 'turquoise_salad_plate']
things = ['lemon', 'brown_ceramic_cup']


def inside_2d(point, box):
    return box[0] <= point[0] <= box[3] and box[1] <= point[1] <= box[4]


empty = None
for plate in plates:
    box = get_3d_bbox(plate)
    if not any(inside_2d(get_object_center_position(t), box) for t in things):
        empty = plate
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('brown_ceramic_cup'))
close_gripper()
attach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
box = get_3d_bbox(empty)
cup = get_3d_bbox('brown_ceramic_cup')
target = np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, box[5] + (cup[5] - cup[2]) / 2])
move_to_pose(parse_place_pose('brown_ceramic_cup', position=target))
open_gripper()
detach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
