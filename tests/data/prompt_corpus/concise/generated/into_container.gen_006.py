# Task: put the red block into the footed bowl.
# Plan:
# 1. Detect the red block and the footed bowl.
# 2. Grasp the block from above at its middle, lift it clear of the bowl's rim.
# 3. Find a place pose inside the bowl, move there, release, move up.
detect_objects(object_list=['red_block', 'footed_bowl'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='red_block', description='center'))
close_gripper()
attach_object('red_block')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose(object_name='red_block', receptacle_name='footed_bowl'))
open_gripper()
detach_object('red_block')
move_in_direction([0, 0, 1], 0.1)
