# Task: move the green block next to the white saucer.
# Plan:
# 1. Target: on the table just left (+y) of the saucer, 3 cm beyond its edge, in line with its centre in x.
# 2. Grasp the green block from above, lift it.
# 3. Place it at the target, release it, move up.
detect_objects()
saucer = get_3d_bbox('white_saucer')
block = get_3d_bbox('green_block')
target = [(saucer[0] + saucer[3]) / 2, saucer[4] + (block[4] - block[1]) / 2 + 0.03, saucer[2]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_block', description='center'))
close_gripper()
attach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='green_block', position=target))
open_gripper()
detach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
