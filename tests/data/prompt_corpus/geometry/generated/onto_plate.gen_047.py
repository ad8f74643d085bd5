# Task: put the green block on the blue saucer.
# Plan:
# 1. Detect the green block and the blue saucer; the target is the middle of the saucer's box in x, y.
# 2. Grasp the block top-down at its middle, attach it, lift it (a Pose from the gripper's).
# 3. Place it on the saucer at the target, release it, move up.
detect_objects(object_list=['green_block', 'blue_saucer'])
saucer_box = get_3d_bbox('blue_saucer')
target = [(saucer_box[0] + saucer_box[3]) / 2.0, (saucer_box[1] + saucer_box[4]) / 2.0, saucer_box[5]]

open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_block', description='center'))
close_gripper()
attach_object('green_block')
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='green_block', receptacle_name='blue_saucer', position=target))
open_gripper()
detach_object('green_block')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
