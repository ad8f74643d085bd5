# Task: place the apple into the footed bowl.
# Plan:
# 1. Detect the apple and the footed bowl.
# 2. Grasp the apple from above at its middle, lift it.
# 3. Place it into the footed bowl, release it, move up.
detect_objects(object_list=['apple', 'footed_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='apple', description='center'))
close_gripper()
attach_object('apple')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='apple', receptacle_name='footed_bowl'))
open_gripper()
detach_object('apple')
move_in_direction([0, 0, 1], 0.1)
