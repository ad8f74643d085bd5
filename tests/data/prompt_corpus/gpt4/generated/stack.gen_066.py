# Task: put the blue block on the red box.
# Plan:
# 1. Detect the blue block and the red box.
# 2. Grasp the blue block from above with an adaptive grasp at its centre, lift it well above the red box.
# 3. Place it on top of the red box, at the box's centre, release it and move up.
detect_objects(['blue_block', 'red_box'])

block_center = get_object_center_position('blue_block')
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('blue_block', preferred_position=block_center, preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('blue_block')
move_in_direction(np.array([0, 0, 1]), 0.15)

box_bbox = get_3d_bbox('red_box')
box_center = get_object_center_position('red_box')
target = np.array([box_center[0], box_center[1], box_bbox[5]])
move_to_pose(parse_place_pose('blue_block', 'red_box', target))
open_gripper()
detach_object('blue_block')
move_in_direction(np.array([0, 0, 1]), 0.1)
