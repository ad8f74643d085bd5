# Task: put the blue mug next to the red mug
# Plan:
# 1. The target is 15 cm to the left (+y) of the red mug's centre, on the table.
# 2. Grasp the blue mug with the adaptive grasp from above (its rim), lift it.
# 3. Place it at the target position, release it, move up.
detect_objects()
red_center = get_object_center_position('red_mug')
target = [red_center[0], red_center[1] + 0.15, red_center[2]]
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='blue_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('blue_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_mug', position=target))
open_gripper()
detach_object('blue_mug')
move_in_direction([0, 0, 1], 0.1)
