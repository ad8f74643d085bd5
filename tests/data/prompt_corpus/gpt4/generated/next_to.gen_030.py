# Task: put the banana next to the tea box.
# Plan:
# 1. Detect the banana and the tea box.
# 2. Compute a target beside the tea box along y: the tea box centre shifted by half its width,
#    half the banana's longest side and a 3 cm gap; take the side towards the middle of the workspace (y = 0).
# 3. Grasp the banana with the adaptive grasp, lift it.
# 4. Place it at the target on the table, release it, move up.
detect_objects(['banana', 'tea_box'])
box_center = get_object_center_position('tea_box')
box_bbox = get_3d_bbox('tea_box')
banana_bbox = get_3d_bbox('banana')
table_top = get_3d_bbox('table')[5]

box_half_width = (box_bbox[4] - box_bbox[1]) / 2
banana_half = max(banana_bbox[3] - banana_bbox[0], banana_bbox[4] - banana_bbox[1]) / 2
side = -1.0 if box_center[1] > 0 else 1.0
target = np.array([box_center[0], box_center[1] + side * (box_half_width + banana_half + 0.03), table_top])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('banana'))
close_gripper()
attach_object('banana')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('banana', position=target))
open_gripper()
detach_object('banana')
move_in_direction([0, 0, 1], 0.1)
