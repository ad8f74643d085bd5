# Task: close the open drawer.
# Plan:
# 1. Rows from the top: drawer_0 (handle_0), drawer_1 (handle_1), door_0 (handle_2).
# 2. Read both drawers' joints near their handles; the open one is the one with the larger joint_value.
# 3. Grasp that drawer's handle horizontally and attach the drawer.
# 4. Push along the joint axis, the opposite way from opening, by as far as it is open.
# 5. Release and back away.
detect_objects()
joint_0 = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='prismatic')
joint_1 = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_1'), type='prismatic')
if joint_0['joint_value'] >= joint_1['joint_value']:
    drawer = 'cabinet.drawer_0'
    handle = 'cabinet.handle_0'
    joint = joint_0
else:
    drawer = 'cabinet.drawer_1'
    handle = 'cabinet.handle_1'
    joint = joint_1
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object(drawer)
move_in_direction(joint['joint_axis'], -joint['joint_value'])
open_gripper()
detach_object(drawer)
move_in_direction(joint['joint_axis'], 0.05)
