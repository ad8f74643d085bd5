# Task: open the cabinet door
# Plan:
# 1. Detect the objects. Rows from the top: drawer_0 (handle_0), drawer_1 (handle_1), door_0 (handle_2).
# 2. Grasp the door handle cabinet.handle_2 from the front of the door.
# 3. Close the gripper and attach cabinet.door_0.
# 4. Find the door's revolute joint near the handle.
# 5. Generate an arc path around the hinge and follow it to swing the door open.
# 6. Release the handle and move the gripper back out of the door's way.
detect_objects()

handle_pos = get_object_center_position('cabinet.handle_2')
front_normal = np.array(get_plane_normal('cabinet.door_0', handle_pos))

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('cabinet.handle_2', preferred_position=handle_pos,
                                      preferred_approach_direction=-front_normal))
close_gripper()
attach_object('cabinet.door_0')

joint = get_object_joint_info('cabinet', handle_pos, 'revolute')
angle = min(60.0, joint['joint_upper'] - joint['joint_value'])
path = generate_arc_path_around_joint(get_gripper_pose(), joint['joint_axis'], joint['joint_position'], 20, angle)
follow_path(path)

open_gripper()
detach_object('cabinet.door_0')

# back away along the gripper's approach axis
pose = get_gripper_pose()
qx, qy, qz, qw = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
approach_axis = np.array([2 * (qx * qz + qw * qy), 2 * (qy * qz - qw * qx), 1 - 2 * (qx * qx + qy * qy)])
move_in_direction(-approach_axis, 0.1)
