# Task: move the gelatin box next to the white bowl.
# Plan:
# 1. Measure the bowl and the gelatin box.
# 2. The target is beside the bowl along y, on the side where the box is now: the bowl's half width,
#    plus half the box's larger footprint side, plus a 3 cm gap from the bowl's centre.
# 3. Grasp the gelatin box from above, lift it.
# 4. Place it at the target position on the table and release it.
detect_objects()
bowl_center = get_object_center_position('white_bowl')
bowl_bbox = get_3d_bbox('white_bowl')
box_center = get_object_center_position('gelatin_box')
box_bbox = get_3d_bbox('gelatin_box')
side = 1.0 if box_center[1] >= bowl_center[1] else -1.0
box_half = max(box_bbox[3] - box_bbox[0], box_bbox[4] - box_bbox[1]) / 2
offset = (bowl_bbox[4] - bowl_bbox[1]) / 2 + box_half + 0.03
target = [bowl_center[0], bowl_center[1] + side * offset, box_center[2]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='gelatin_box', description='center'))
close_gripper()
attach_object('gelatin_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='gelatin_box', position=target))
open_gripper()
detach_object('gelatin_box')
move_in_direction([0, 0, 1], 0.1)
