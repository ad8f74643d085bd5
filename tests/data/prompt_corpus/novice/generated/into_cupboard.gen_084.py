# Task: open the cabinet door, then place the blue box inside the cabinet.
# Plan:
# 1. The door is listed above the drawer, so it is the top row: its handle is cabinet.handle_0.
# 2. Grasp the door's handle horizontally, attach the door, turn it 60 degrees about its hinge (40 or more is needed).
# 3. Release the handle and move back along the gripper's approach axis.
# 4. Detect again, since the door moved.
# 5. Grasp the blue box horizontally (needed to carry it level into the compartment), lift it.
# 6. Place it into the compartment behind the door, release it, back out along the approach axis.
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
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='blue_box'))
close_gripper()
attach_object('blue_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_box', receptacle_name='cabinet.door_0'))
open_gripper()
detach_object('blue_box')
pose = get_gripper_pose()
qx, qy, qz, qw = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
approach = np.array([2 * (qx * qz + qw * qy), 2 * (qy * qz - qw * qx), 1 - 2 * (qx * qx + qy * qy)])
move_in_direction(-approach, 0.1)
