# Task: put the brown box on the yellow plate.
# Plan:
# 1. Detect the brown box and the yellow plate.
# 2. Grasp the box from above at its middle, lift it.
# 3. Find a place pose on the plate, move there, release, move up.
detect_objects(object_list=['brown_box', 'yellow_plate'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='brown_box', description='center'))
close_gripper()
attach_object('brown_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='brown_box', receptacle_name='yellow_plate'))
open_gripper()
detach_object('brown_box')
move_in_direction([0, 0, 1], 0.1)
