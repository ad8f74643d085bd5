# Task: open the second top cabinet drawer and place all boxes into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1.
# 2. Grasp the handle horizontally, attach the drawer, pull it open along its prismatic joint axis.
# 3. Release the handle, back away, detect again since the drawer moved.
# 4. The boxes are the objects whose names end with '_box': white_and_pink_box, brown_box.
# 5. For each box: grasp it, lift it, place it into the open drawer, release it, move up.
detect_objects()

# 1-3: open the drawer
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
handle_pos = get_object_center_position('cabinet.handle_1')
joint_info = get_object_joint_info('cabinet', handle_pos, 'prismatic')
move_in_direction(joint_info['joint_axis'], min(0.25, joint_info['joint_upper'] - joint_info['joint_value']))
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint_info['joint_axis'], 0.05)
detect_objects()

# 4-5: put the boxes into the drawer
boxes = [name for name in get_object_name_list() if name.endswith('_box')]
for box in boxes:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(box))
    close_gripper()
    attach_object(box)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(box, 'cabinet.drawer_1'))
    open_gripper()
    detach_object(box)
    move_in_direction([0, 0, 1], 0.08)
