# Task: place the brown ceramic cup beside the pear.
# Plan:
# 1. Detect everything; take the pear's centre.
# 2. Candidates beside it: 12 cm to its left (+y) or right (-y); choose the one farther from the other objects.
# 3. Grasp the cup with the adaptive grasp from above (by its rim; a cup may be wider than the opening), close, attach, lift.
# 4. Place it at the chosen spot, release it and move up.
detect_objects()
p = get_object_center_position('pear')
others = [get_object_center_position(n) for n in ('footed_bowl', 'rubiks_cube', 'medication_bottle')]
t = max((p + [0, s, 0] for s in (0.12, -0.12)), key=lambda t: min(np.linalg.norm((t - o)[:2]) for o in others))
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('brown_ceramic_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('brown_ceramic_cup', position=t))
open_gripper()
detach_object('brown_ceramic_cup')
move_in_direction([0, 0, 1], 0.1)
