# Task: place the red block on top of the brown box.
# Plan:
# 1. Detect the block and the box; the target is the middle of the brown box's top (its box's middle in x, y).
# 2. Grasp the red block top-down at its middle, attach it, and lift it (a Pose from the gripper's) until its
#    bottom is 5 cm above the brown box's top.
# 3. Place it on the brown box at the target, release it, move up.
detect_objects(object_list=['red_block', 'brown_box'])
box = get_3d_bbox('brown_box')
target = [(box[0] + box[3]) / 2.0, (box[1] + box[4]) / 2.0, box[5]]

block_bottom = get_object_pose('red_block').position.z
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='red_block', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('red_block')
hold = grasp_pose.position.z - block_bottom
lift = get_gripper_pose()
lift.position.z = max(lift.position.z + 0.1, box[5] + hold + 0.05)
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='red_block', receptacle_name='brown_box', position=target))
open_gripper()
detach_object('red_block')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
