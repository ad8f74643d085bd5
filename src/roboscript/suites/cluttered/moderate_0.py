# Task: open the second top cabinet drawer and place all boxes into it.
# Plan:
# 1. Detect the cabinet and the boxes.
# 2. Grasp the handle of the second drawer from the top (cabinet.handle_1) horizontally, close the gripper.
# 3. Pull the drawer open along its joint axis, release the handle and back away from it.
# 4. For every box: grasp it from above, lift it, place it into the open drawer, release it and move up.
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
boxes = [name for name in get_object_name_list() if name.endswith('_box')]
for box in boxes:
    grasp_pose = parse_central_lift_grasp_pose(object_name=box, description='center')
    grasp(grasp_pose)
    close_gripper()
    attach_object(box)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
    place_pose = parse_place_pose(object_name=box, receptacle_name='cabinet.drawer_1')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(box)
    move_in_direction(direction=[0, 0, 1], distance=0.08)
