# Task: put the strawberry next to the red block.
# Plan:
# 1. Detect the objects and take the red block's centre.
# 2. The target is 10 cm to the left (+y) of the red block, on the table.
# 3. Grasp the strawberry from above, lift it.
# 4. Place it at the target position, release it, move up.
detect_objects()
block_center = get_object_center_position('red_block')
target = [block_center[0], block_center[1] + 0.1, block_center[2]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='strawberry', description='center'))
close_gripper()
attach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='strawberry', position=target))
open_gripper()
detach_object('strawberry')
move_in_direction([0, 0, 1], 0.1)
