# query: objects = [table, orange, red_bowl, sponge] ; # put the orange into the red bowl
# Plan:
# 1. Detect the orange and the red bowl.
# 2. Grasp the orange from above at its middle, lift it.
# 3. Find a place pose inside the bowl, move there, release, move up.
detect_objects(object_list=['orange', 'red_bowl'])
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='orange', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('orange')
move_in_direction([0, 0, 1], 0.1)
place_pose = parse_place_pose(object_name='orange', receptacle_name='red_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('orange')
move_in_direction([0, 0, 1], 0.1)
