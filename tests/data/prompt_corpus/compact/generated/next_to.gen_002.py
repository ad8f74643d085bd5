# Task: put the white and pink box next to the white mug
# Plan:
# 1. Measure the box and the mug; the target is beside the mug along y, on the side where the box already is,
#    offset by half the mug's width + half the box's width + a 3 cm gap.
# 2. Grasp the box from above at its middle, lift it.
# 3. Place it at the target on the table, release it, move up.
detect_objects()
mug_box = get_3d_bbox('white_mug')
box_box = get_3d_bbox('white_and_pink_box')
mug_at = get_object_center_position('white_mug')
box_at = get_object_center_position('white_and_pink_box')
side = 1.0 if box_at[1] >= mug_at[1] else -1.0
offset = (mug_box[4] - mug_box[1]) / 2 + (box_box[4] - box_box[1]) / 2 + 0.03
target = [mug_at[0], mug_at[1] + side * offset, get_3d_bbox('table')[5]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='white_and_pink_box', description='center'))
close_gripper()
attach_object('white_and_pink_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_and_pink_box', position=target))
open_gripper()
detach_object('white_and_pink_box')
move_in_direction([0, 0, 1], 0.1)
