# Task: put the medication bottle on the white saucer.
# Plan:
# 1. Detect the medication bottle and the white saucer.
# 2. Grasp the bottle from above with an adaptive grasp near its top, and lift it.
# 3. Place it on the white saucer at the saucer's centre, release it and move up.
detect_objects(['medication_bottle', 'white_saucer'])

bottle_bbox = get_3d_bbox('medication_bottle')
bottle_center = get_object_center_position('medication_bottle')
grasp_point = np.array([bottle_center[0], bottle_center[1], bottle_bbox[5] - 0.02])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('medication_bottle', preferred_position=grasp_point, preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('medication_bottle')
move_in_direction(np.array([0, 0, 1]), 0.1)

saucer_center = get_object_center_position('white_saucer')
move_to_pose(parse_place_pose('medication_bottle', 'white_saucer', saucer_center))
open_gripper()
detach_object('medication_bottle')
move_in_direction(np.array([0, 0, 1]), 0.1)
