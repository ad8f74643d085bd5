# Task: stack the green block on top of the red box.
# Plan:
# 1. Grasp the green block from above, lift it higher than the red box.
# 2. Place it onto the red box's top and release it.
# 3. Move up.
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_block', description='center'))
close_gripper()
attach_object('green_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='green_block', receptacle_name='red_box'))
open_gripper()
detach_object('green_block')
move_in_direction([0, 0, 1], 0.1)
