# The mug's body is wider than the gripper opens: the adaptive grasp, from above, closing along x (across the
# rim nearest the robot); it goes onto the plate of its colour.
detect_objects()
names = get_object_name_list()
mug = 'white_porcelain_mug'
target = next(n for n in names if n != mug and n.startswith('white') and ('plate' in n or 'saucer' in n))
open_gripper()
grasp(parse_adaptive_shape_grasp_pose(mug, preferred_approach_direction=[0, 0, -1], preferred_plane_normal=[1, 0, 0]))
close_gripper()
attach_object(mug)
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(mug, target))
open_gripper()
detach_object(mug)
move_in_direction([0, 0, 1], 0.1)
