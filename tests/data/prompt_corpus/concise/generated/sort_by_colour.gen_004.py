# Task: sort the objects on the table by colour: put the green objects on the green plate.
# Plan:
# 1. Besides the plate itself, the only green object is the green apple.
# 2. Grasp the green apple from above, lift it.
# 3. Place it onto the green plate, release it, move up.
detect_objects(object_list=['green_apple', 'green_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_apple', description='center'))
close_gripper()
attach_object('green_apple')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='green_apple', receptacle_name='green_plate'))
open_gripper()
detach_object('green_apple')
move_in_direction([0, 0, 1], 0.1)
