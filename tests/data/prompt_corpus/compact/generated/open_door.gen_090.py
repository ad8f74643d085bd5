# Task: open the cabinet door wide
# Plan:
# 1. Handles are numbered by row with drawers and doors counted together: take the handle whose height is
#    closest to the door's centre.
# 2. Grasp it horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint near the handle and follow an arc about the hinge, about 90 degrees
#    (no more than the joint allows), for a wide opening.
# 4. Release the handle and back out along the hand's approach axis.
detect_objects()
door_z = get_object_center_position('cabinet.door_0')[2]
handle = min(['cabinet.handle_0', 'cabinet.handle_1'], key=lambda h: abs(get_object_center_position(h)[2] - door_z))
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
angle = min(90.0, joint['joint_upper'] - joint['joint_value'])
follow_path(generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=30, angle=angle))
open_gripper()
detach_object('cabinet.door_0')
q = get_gripper_pose().orientation
approach = np.array([2 * (q.x * q.z + q.w * q.y), 2 * (q.y * q.z - q.w * q.x), 1 - 2 * (q.x * q.x + q.y * q.y)])
move_in_direction(-approach, 0.08)
