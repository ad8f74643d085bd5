# Task: place the gelatin box onto the green plate.
# Plan:
# 1. Detect the gelatin box and the green plate.
# 2. Grasp the gelatin box from above at its middle, lift it.
# 3. Find a place pose on the plate, move there, release, move up.
detect_objects(object_list=['gelatin_box', 'green_plate'])
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='gelatin_box', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('gelatin_box')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose(object_name='gelatin_box', receptacle_name='green_plate')
move_to_pose(place_pose)
open_gripper()
detach_object('gelatin_box')
move_in_direction([0, 0, 1], 0.1)
