# Task: close the open drawer
# Plan:
# 1. Detect the objects. The drawers are cabinet.drawer_0 (handle_0) and cabinet.drawer_1 (handle_1).
# 2. Find which drawer is open: get each drawer's prismatic joint and compare joint_value (how far it is open).
# 3. Grasp the open drawer's handle, close the gripper and attach the drawer.
# 4. Push it shut along -joint_axis by as far as it is open.
# 5. Release the handle and back away along +joint_axis.
detect_objects()

drawers = {'cabinet.drawer_0': 'cabinet.handle_0', 'cabinet.drawer_1': 'cabinet.handle_1'}

open_drawer = None
open_joint = None
for drawer, handle in drawers.items():
    joint = get_object_joint_info('cabinet', get_object_center_position(handle), 'prismatic')
    if open_joint is None or joint['joint_value'] > open_joint['joint_value']:
        open_drawer = drawer
        open_joint = joint

handle = drawers[open_drawer]
handle_pos = get_object_center_position(handle)
axis = np.array(open_joint['joint_axis'])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(handle, handle_pos, -axis))
close_gripper()
attach_object(open_drawer)

move_in_direction(axis, -open_joint['joint_value'])

open_gripper()
detach_object(open_drawer)
move_in_direction(axis, 0.05)
