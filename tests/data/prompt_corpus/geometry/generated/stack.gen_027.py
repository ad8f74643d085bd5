# Task: put the wooden block on the brown box.
# Plan:
# 1. Detect the block and the box; the target is the middle of the brown box's top (its box's middle in x, y).
# 2. Grasp the wooden block (top-down at its middle if its box is narrower than the fingers open, else the
#    adaptive grasp near its middle), attach it, and lift it (a Pose from the gripper's) until its
#    bottom is 5 cm above the brown box's top.
# 3. Place it on the brown box at the target, release it, move up.
detect_objects(object_list=['wooden_block', 'brown_box'])
box = get_3d_bbox('brown_box')
target = [(box[0] + box[3]) / 2.0, (box[1] + box[4]) / 2.0, box[5]]

block_bottom = get_object_pose('wooden_block').position.z
open_gripper()
block_box = get_3d_bbox('wooden_block')
if min(block_box[3] - block_box[0], block_box[4] - block_box[1]) < 0.07:
    grasp_pose = parse_central_lift_grasp_pose(object_name='wooden_block', description='center')
else:
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name='wooden_block', preferred_position=get_object_center_position('wooden_block'), preferred_approach_direction=[0, 0, -1])
grasp(grasp_pose)
close_gripper()
attach_object('wooden_block')
hold = grasp_pose.position.z - block_bottom
lift = get_gripper_pose()
lift.position.z = max(lift.position.z + 0.1, box[5] + hold + 0.05)
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='wooden_block', receptacle_name='brown_box', position=target))
open_gripper()
detach_object('wooden_block')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
