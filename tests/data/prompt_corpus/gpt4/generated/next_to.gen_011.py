# Task: put the blue mug next to the red mug.
# Plan:
# 1. Detect both mugs and measure their boxes.
# 2. The target is beside the red mug along y, on the side towards the middle of the workspace (y = 0),
#    the centres apart by half of each mug's width + a 3 cm gap.
# 3. Grasp the blue mug from above with an adaptive grasp (rim or handle) and lift it.
# 4. Place it at the target on the table, release it and move up.
detect_objects(['blue_mug', 'red_mug'])

red_center = get_object_center_position('red_mug')
red_bbox = get_3d_bbox('red_mug')
blue_bbox = get_3d_bbox('blue_mug')
red_half_width = (red_bbox[4] - red_bbox[1]) / 2
blue_half_width = (blue_bbox[4] - blue_bbox[1]) / 2
offset = red_half_width + blue_half_width + 0.03
side = -1.0 if red_center[1] > 0 else 1.0
target = np.array([red_center[0], red_center[1] + side * offset, red_center[2]])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('blue_mug', preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('blue_mug')
move_in_direction(np.array([0, 0, 1]), 0.1)

move_to_pose(parse_place_pose('blue_mug', position=target))
open_gripper()
detach_object('blue_mug')
move_in_direction(np.array([0, 0, 1]), 0.1)
