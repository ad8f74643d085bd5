# Task: put the blue block on the red box.
# Plan:
# 1. Grasp the blue block from above, lift it higher than the red box.
# 2. Place it onto the red box ('on' placement uses the receptacle's top) and release it.
# 3. Move up.
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='blue_block', description='center'))
close_gripper()
attach_object('blue_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='red_box'))
open_gripper()
detach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)
