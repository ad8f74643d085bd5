# Task: close the open drawer.
# Plan:
# 1. Detect everything. The drawers are cabinet.drawer_0 (handle_0) and cabinet.drawer_1 (handle_1); handle_2 is the door's.
# 2. Read each drawer's prismatic joint near its handle; the open one is the one with the larger joint_value.
# 3. Grasp its handle horizontally, close the gripper, attach the drawer.
# 4. Push along -axis by as far as it is open, release, and back away along +axis.
detect_objects()
js = [get_object_joint_info(f'cabinet.drawer_{i}', get_object_center_position(f'cabinet.handle_{i}'), 'prismatic') for i in (0, 1)]
i = int(np.argmax([j['joint_value'] for j in js]))
j = js[i]
open_gripper()
grasp(parse_horizontal_grasp_pose(f'cabinet.handle_{i}'))
close_gripper()
attach_object(f'cabinet.drawer_{i}')
move_in_direction(j['joint_axis'], -j['joint_value'])
open_gripper()
detach_object(f'cabinet.drawer_{i}')
move_in_direction(j['joint_axis'], 0.05)
