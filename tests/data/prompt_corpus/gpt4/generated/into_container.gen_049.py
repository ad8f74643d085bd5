# Task: put the rubiks cube into the white bowl.
# Plan:
# 1. Detect the rubiks cube and the white bowl.
# 2. Grasp the rubiks cube from above with an adaptive grasp at its centre, and lift it.
# 3. Place it into the white bowl, release it and move up.
detect_objects(['rubiks_cube', 'white_bowl'])

cube_center = get_object_center_position('rubiks_cube')

open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('rubiks_cube', preferred_position=cube_center, preferred_approach_direction=np.array([0, 0, -1]))
grasp(grasp_pose)
close_gripper()
attach_object('rubiks_cube')
move_in_direction(np.array([0, 0, 1]), 0.1)

place_pose = parse_place_pose('rubiks_cube', 'white_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('rubiks_cube')
move_in_direction(np.array([0, 0, 1]), 0.1)
