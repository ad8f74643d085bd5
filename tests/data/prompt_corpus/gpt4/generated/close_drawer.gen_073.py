# Task: close the open drawer.
# Plan:
# 1. The cabinet has two drawers above a door: cabinet.handle_0 and cabinet.handle_1 are the drawers' handles.
# 2. Find which drawer is open: the one whose prismatic joint has the largest joint value.
# 3. Grasp that drawer's handle horizontally and attach the drawer.
# 4. Push along the joint axis, the opposite way from opening, by as far as it is open.
# 5. Release and back away.
detect_objects()
drawers = ['cabinet.drawer_0', 'cabinet.drawer_1']
handles = ['cabinet.handle_0', 'cabinet.handle_1']
joints = [get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic') for handle in handles]
i = int(np.argmax([joint['joint_value'] for joint in joints]))
drawer, handle, joint = drawers[i], handles[i], joints[i]
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object(drawer)
move_in_direction(joint['joint_axis'], -joint['joint_value'])
open_gripper()
detach_object(drawer)
move_in_direction(joint['joint_axis'], 0.05)
