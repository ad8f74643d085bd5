# Task: put the pear on the white plate.
# Plan:
# 1. Detect the pear and the white plate.
# 2. Grasp the pear with the adaptive grasp, lift it.
# 3. Place it on the plate, near the plate's centre, release it and move up.
detect_objects(['pear', 'white_plate'])
plate_center = get_object_center_position('white_plate')
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('pear'))
close_gripper()
attach_object('pear')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose('pear', 'white_plate', plate_center)
move_to_pose(place_pose)
open_gripper()
detach_object('pear')
move_in_direction([0, 0, 1], 0.1)
