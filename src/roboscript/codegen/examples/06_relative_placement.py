# query: objects = [table, white_mug, cracker_box] ; # put the mug 15 cm to the left of the cracker box
# Plan:
# 1. Left is +y in the robot's frame: the target is the box centre moved 0.15 m along +y, on the table.
# 2. Grasp the mug with the adaptive grasp from above (its rim), lift it.
# 3. Place it at the target position and release it.
detect_objects()
box_center = get_object_center_position('cracker_box')
target = [box_center[0], box_center[1] + 0.15, box_center[2]]
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='white_mug', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('white_mug')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='white_mug', position=target))
open_gripper()
detach_object('white_mug')
move_in_direction([0, 0, 1], 0.1)
