# Task: place the mug into the second top drawer.
# Plan:
# 1. Detect the cabinet and the mug.
# 2. The drawer is closed: grasp the handle of the second drawer (cabinet.handle_1) horizontally, pull the
#    drawer open along its joint axis, release the handle and back away from it.
# 3. Grasp the mug with the adaptive grasp from above, lift it.
# 4. Place it into the open drawer, release it, move up.
detect_objects()
open_gripper()
handle_pose = parse_horizontal_grasp_pose(object_name='cabinet.handle_1')
grasp(handle_pose)
close_gripper()
attach_object('cabinet.drawer_1')
joint_info = get_object_joint_info(obj_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
axis = joint_info['joint_axis']
move_in_direction(axis, distance=0.22)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(axis, distance=0.03)
grasp_pose = parse_adaptive_shape_grasp_pose(object_name='white_and_yellow_mug', preferred_approach_direction=[0, 0, -1])
grasp(grasp_pose)
close_gripper()
attach_object('white_and_yellow_mug')
move_in_direction(direction=[0, 0, 1], distance=0.1)
place_pose = parse_place_pose(object_name='white_and_yellow_mug', receptacle_name='cabinet.drawer_1')
move_to_pose(place_pose)
open_gripper()
detach_object('white_and_yellow_mug')
move_in_direction(direction=[0, 0, 1], distance=0.05)
