# Task: close the open drawer
# Plan:
# 1. Detect the objects. Two drawers: cabinet.drawer_0 with cabinet.handle_0, cabinet.drawer_1 with cabinet.handle_1.
# 2. Read the prismatic joint near each handle; the open drawer is the one with the largest joint_value.
# 3. Grasp that drawer's handle horizontally against the drawer front, close the gripper, attach the drawer.
# 4. Push along the joint axis in the negative direction by the opening distance.
# 5. Open the gripper, detach the drawer and pull the hand back a little.
detect_objects()

handles = ['cabinet.handle_0', 'cabinet.handle_1']
drawer_names = ['cabinet.drawer_0', 'cabinet.drawer_1']

joints = [get_object_joint_info('cabinet', get_object_center_position(h), 'prismatic') for h in handles]
opening = np.array([j['joint_value'] for j in joints])
i = int(np.argmax(opening))

handle, drawer, joint = handles[i], drawer_names[i], joints[i]
joint_axis = np.array(joint['joint_axis'])

open_gripper()
grasp(parse_horizontal_grasp_pose(handle, -joint_axis))
close_gripper()
attach_object(drawer)

move_in_direction(joint_axis, -joint['joint_value'])

open_gripper()
detach_object(drawer)
move_in_direction(joint_axis, 0.05)
