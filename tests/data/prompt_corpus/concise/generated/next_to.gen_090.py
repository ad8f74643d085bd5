# Task: put the plum next to the rubiks cube
# Plan:
# 1. The target is 10 cm to the left (+y) of the cube's centre, on the table.
# 2. Grasp the plum from above at its middle, lift it.
# 3. Place it at the target position, release it, move up.
detect_objects()
cube_center = get_object_center_position('rubiks_cube')
target = [cube_center[0], cube_center[1] + 0.1, cube_center[2]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='plum', description='center'))
close_gripper()
attach_object('plum')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='plum', position=target))
open_gripper()
detach_object('plum')
move_in_direction([0, 0, 1], 0.1)
