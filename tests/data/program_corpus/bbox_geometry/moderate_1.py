# Same colour as the mug: the container whose name shares the mug's first word, placed at its box's middle.
detect_objects()
mug = 'white_porcelain_mug'
plate = 'white_ceramic_plate'
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(mug, preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object(mug)
move_in_direction([0, 0, 1], 0.1)
box = get_3d_bbox(plate)
mug_box = get_3d_bbox(mug)
center = [(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, box[5] + (mug_box[5] - mug_box[2]) / 2]
move_to_pose(parse_place_pose(mug, position=center))
open_gripper()
detach_object(mug)
move_in_direction([0, 0, 1], 0.1)
