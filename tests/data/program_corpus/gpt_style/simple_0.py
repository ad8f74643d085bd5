# Grasp the apple
open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('apple')
grasp(grasp_pose)
close_gripper()
attach_object('apple')

# Place the apple into the footed bowl
place_pose = parse_place_pose('apple', 'footed_bowl')
move_to_pose(place_pose)
open_gripper()
detach_object('apple')
