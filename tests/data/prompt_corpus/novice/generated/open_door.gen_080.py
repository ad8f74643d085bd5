# Task: open the cabinet door.
# Plan:
# 1. The door is listed above the drawer, so it is the top row: its handle is cabinet.handle_0.
# 2. Grasp the door's handle horizontally and attach the door.
# 3. The door turns about a revolute joint: get its axis and position near the handle.
# 4. Follow an arc about the hinge from the present gripper pose, in small steps.
# 5. Release the handle and move back along the gripper's approach axis, out of the door's way.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='revolute')
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=60)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
pose = get_gripper_pose()
qx, qy, qz, qw = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
approach = np.array([2 * (qx * qz + qw * qy), 2 * (qy * qz - qw * qx), 1 - 2 * (qx * qx + qy * qy)])
move_in_direction(-approach, 0.08)
