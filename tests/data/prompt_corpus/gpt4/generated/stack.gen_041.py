# Task: place the red block on top of the gelatin box.
# Plan:
# 1. Detect the red block and the gelatin box.
# 2. Grasp the red block, lift it above the gelatin box.
# 3. Place it on the top of the gelatin box, at the box's centre, release it, move up.
detect_objects(['red_block', 'gelatin_box'])
box_center = get_object_center_position('gelatin_box')
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('red_block'))
close_gripper()
attach_object('red_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose('red_block', 'gelatin_box', box_center))
open_gripper()
detach_object('red_block')
move_in_direction([0, 0, 1], 0.1)
