# Remember where the apple and the banana are
apple_position = get_object_center_position('apple')
banana_position = get_object_center_position('banana')

# Move the apple out of the way, onto a free place on the table
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('apple'))
close_gripper()
attach_object('apple')
move_to_pose(parse_place_pose('apple', 'table'))
open_gripper()
detach_object('apple')

# Move the banana to where the apple was
grasp(parse_adaptive_shape_grasp_pose('banana'))
close_gripper()
attach_object('banana')
move_to_pose(parse_place_pose('banana', position=apple_position))
open_gripper()
detach_object('banana')

# Move the apple to where the banana was
grasp(parse_adaptive_shape_grasp_pose('apple'))
close_gripper()
attach_object('apple')
move_to_pose(parse_place_pose('apple', position=banana_position))
open_gripper()
detach_object('apple')
