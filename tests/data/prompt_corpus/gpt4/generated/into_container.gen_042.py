# Task: put the white medication bottle into the footed bowl.
# Plan:
# 1. Detect the white medication bottle and the footed bowl.
# 2. Grasp the bottle with an adaptive grasp from above, near the top of its box, and lift it.
# 3. Get a place pose inside the footed bowl (at the bowl's centre), move there, release, move up.
detect_objects(['white_medication_bottle', 'footed_bowl'])

bottle_bbox = get_3d_bbox('white_medication_bottle')
bottle_center = get_object_center_position('white_medication_bottle')
grasp_point = np.array([bottle_center[0], bottle_center[1], bottle_bbox[5] - 0.02])

open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('white_medication_bottle', preferred_position=grasp_point, preferred_approach_direction=np.array([0, 0, -1]))
grasp(grasp_pose)
close_gripper()
attach_object('white_medication_bottle')
move_in_direction(np.array([0, 0, 1]), 0.1)

bowl_center = get_object_center_position('footed_bowl')
place_pose = parse_place_pose('white_medication_bottle', 'footed_bowl', bowl_center)
move_to_pose(place_pose)
open_gripper()
detach_object('white_medication_bottle')
move_in_direction(np.array([0, 0, 1]), 0.1)
