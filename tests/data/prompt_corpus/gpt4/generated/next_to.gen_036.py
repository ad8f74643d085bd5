# Task: place the strawberry beside the pink saucer.
# Plan:
# 1. Detect the strawberry and the pink saucer.
# 2. Target: the saucer centre moved sideways (along y) by half the saucer's width,
#    half the strawberry's width and a 3 cm gap, on the side towards y = 0.
# 3. Grasp the strawberry, lift it, place it at the target on the table, release, move up.
detect_objects(['strawberry', 'pink_saucer'])
saucer_center = get_object_center_position('pink_saucer')
saucer_bbox = get_3d_bbox('pink_saucer')
berry_bbox = get_3d_bbox('strawberry')

offset = (saucer_bbox[4] - saucer_bbox[1]) / 2 + max(berry_bbox[3] - berry_bbox[0], berry_bbox[4] - berry_bbox[1]) / 2 + 0.03
direction = np.array([0, -1, 0]) if saucer_center[1] > 0 else np.array([0, 1, 0])
target = saucer_center + offset * direction

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('strawberry'))
close_gripper()
attach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('strawberry', 'table', target))
open_gripper()
detach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
