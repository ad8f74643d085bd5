# Task: put the plum next to the rubiks cube.
# Plan:
# 1. Detect the plum and the rubiks cube, measure their boxes.
# 2. The target is beside the cube along y, on the side towards the middle of the workspace (y = 0),
#    the centres apart by half the cube's width + half the plum's width + a 3 cm gap.
# 3. Grasp the plum from above with an adaptive grasp and lift it.
# 4. Place it at the target on the table, release it and move up.
detect_objects(['plum', 'rubiks_cube'])

cube_center = get_object_center_position('rubiks_cube')
cube_bbox = get_3d_bbox('rubiks_cube')
plum_bbox = get_3d_bbox('plum')
cube_half_width = (cube_bbox[4] - cube_bbox[1]) / 2
plum_half_width = (plum_bbox[4] - plum_bbox[1]) / 2
offset = cube_half_width + plum_half_width + 0.03
side = -1.0 if cube_center[1] > 0 else 1.0
target = np.array([cube_center[0], cube_center[1] + side * offset, cube_center[2]])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('plum', preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('plum')
move_in_direction(np.array([0, 0, 1]), 0.1)

move_to_pose(parse_place_pose('plum', position=target))
open_gripper()
detach_object('plum')
move_in_direction(np.array([0, 0, 1]), 0.1)
