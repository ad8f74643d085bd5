# Task: open the second drawer of the cabinet and put the golf ball into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, opened by cabinet.handle_1.
# 2. Grasp the handle horizontally, attach the drawer and pull it open along its prismatic joint axis.
# 3. Release the handle, back away and detect the objects again.
# 4. Grasp the golf ball, lift it, place it into the drawer, release it and move up.
detect_objects()


def open_drawer(handle, drawer, distance=0.2):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(handle))
    close_gripper()
    attach_object(drawer)
    joint_info = get_object_joint_info('cabinet', get_object_center_position(handle), 'prismatic')
    axis = np.array(joint_info['joint_axis'])
    move_in_direction(axis, min(distance, joint_info['joint_upper'] - joint_info['joint_value']))
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, 0.05)


open_drawer('cabinet.handle_1', 'cabinet.drawer_1')
detect_objects()

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('golf_ball'))
close_gripper()
attach_object('golf_ball')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose('golf_ball', 'cabinet.drawer_1'))
open_gripper()
detach_object('golf_ball')
move_in_direction([0, 0, 1], 0.08)
