# Task: set the white mug down on the yellow plate.
# Plan:
# 1. Detect the white mug and the yellow plate.
# 2. Grasp the mug from above with an adaptive grasp (by its rim or handle) and lift it.
# 3. Place it on the yellow plate at the plate's centre, release it and move up.
detect_objects(['white_mug', 'yellow_plate'])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('white_mug', preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('white_mug')
move_in_direction(np.array([0, 0, 1]), 0.1)

plate_center = get_object_center_position('yellow_plate')
move_to_pose(parse_place_pose('white_mug', 'yellow_plate', plate_center))
open_gripper()
detach_object('white_mug')
move_in_direction(np.array([0, 0, 1]), 0.1)
