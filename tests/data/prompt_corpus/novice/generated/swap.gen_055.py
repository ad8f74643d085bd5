# Task: swap the positions of the lime and the plum.
# Plan:
# 1. Remember both positions before anything moves.
# 2. Move the lime aside to a free spot on the table, so that its place is free.
# 3. Move the plum to where the lime was.
# 4. Move the lime to where the plum was.
detect_objects()
lime_at = get_object_center_position('lime')
plum_at = get_object_center_position('plum')

# 2. Lime aside on the table.
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='lime', description='center'))
close_gripper()
attach_object('lime')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='lime', receptacle_name='table'))
open_gripper()
detach_object('lime')
move_in_direction([0, 0, 1], 0.1)

# 3. Plum to the lime's old place.
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='plum', description='center'))
close_gripper()
attach_object('plum')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='plum', position=lime_at))
open_gripper()
detach_object('plum')
move_in_direction([0, 0, 1], 0.1)

# 4. Lime to the plum's old place.
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='lime', description='center'))
close_gripper()
attach_object('lime')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='lime', position=plum_at))
open_gripper()
detach_object('lime')
move_in_direction([0, 0, 1], 0.1)
