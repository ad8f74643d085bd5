# The empty plate holds nothing in its 2D region; the cup is taken by its rim, approached from above.
detect_objects()
names = get_object_name_list()
candidates = []
for plate in [n for n in names if 'plate' in n]:
    box = get_3d_bbox(plate)
    occupants = [n for n in names
                 if n not in (plate, 'table', 'cabinet', 'brown_ceramic_cup') and '.' not in n
                 and box[0] < get_object_center_position(n)[0] < box[3]
                 and box[1] < get_object_center_position(n)[1] < box[4]]
    if not occupants:
        candidates.append(plate)
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('brown_ceramic_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('brown_ceramic_cup', candidates[0]))
open_gripper()
detach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
