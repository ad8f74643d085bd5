# Task: move the white mug into a container with the same colour (colours are in the names).
# Plan:
# 1. The mug is white_porcelain_mug; the containers are green_plant_plate, white_ceramic_plate and
#    red_plant_saucer, and the white one is white_ceramic_plate.
# 2. Detect; the target is the middle of the white plate's box in x, y.
# 3. Grasp the mug by its rim from above with the adaptive grasp, attach it, lift it (a Pose from the gripper's).
# 4. Place it on the white plate at the target, release it, move up.
detect_objects()
container = 'white_ceramic_plate'
plate_box = get_3d_bbox(container)
target = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='white_porcelain_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_porcelain_mug')
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='white_porcelain_mug', receptacle_name=container, position=target))
open_gripper()
detach_object('white_porcelain_mug')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
