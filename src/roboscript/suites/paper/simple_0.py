# Task: place the apple into the footed bowl.
# Plan:
# 1. Detect the apple and the footed bowl.
# 2. Grasp the apple from above at its centre (it is round), close the gripper and attach it.
# 3. Lift the apple clear of the table.
# 4. Find a free pose inside the footed bowl, move there and release the apple.
# 5. Move the gripper up and away.
detect_objects(category_list=['apple', 'footed_bowl'])
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='apple', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('apple')
move_in_direction(direction=[0, 0, 1], distance=0.1)
place_pose = parse_place_pose(object_name='apple', receptacle_name='footed_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('apple')
move_in_direction(direction=[0, 0, 1], distance=0.1)
