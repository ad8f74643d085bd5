# Task: place the red box onto the green plate.
# Plan:
# 1. Detect the red box and the green plate.
# 2. Grasp the red box from above, lift it.
# 3. Place it onto the plate, release it, move up.
detect_objects(object_list=['red_box', 'green_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='red_box', description='center'))
close_gripper()
attach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='red_box', receptacle_name='green_plate'))
open_gripper()
detach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
