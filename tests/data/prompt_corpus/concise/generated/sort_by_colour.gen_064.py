# Task: sort the objects on the table by colour: put the green objects into the green bowl.
# Plan:
# 1. The green objects on the table: green_block (green_bowl is the receptacle itself).
# 2. Grasp the green block from above, lift it.
# 3. Place it into the green bowl, release it, move up.
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_block', description='center'))
close_gripper()
attach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='green_block', receptacle_name='green_bowl'))
open_gripper()
detach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
