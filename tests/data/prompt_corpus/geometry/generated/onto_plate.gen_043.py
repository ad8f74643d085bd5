# Task: put the lemon on the yellow plate.
# Plan:
# 1. Detect the lemon and the yellow plate; the target is the middle of the plate's box in x, y.
# 2. Grasp the lemon top-down at its middle, attach it, lift it (a Pose from the gripper's).
# 3. Place it on the plate at the target, release it, move up.
detect_objects(object_list=['lemon', 'yellow_plate'])
plate_box = get_3d_bbox('yellow_plate')
target = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]

open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='lemon', description='center'))
close_gripper()
attach_object('lemon')
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='lemon', receptacle_name='yellow_plate', position=target))
open_gripper()
detach_object('lemon')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
