# Task: open the cabinet door wide.
# Plan:
# 1. The cabinet has two drawers above one door: the door is cabinet.door_0 and its handle is on the
#    third row from the top, cabinet.handle_2.
# 2. Grasp the door's handle horizontally, close the gripper, attach the door.
# 3. Read the door's revolute joint near the handle: how far it is open now (joint_value) and how far it
#    opens at most (joint_upper), both in degrees.
# 4. "Wide": turn the hand about the hinge through nearly all of the remaining range (leaving a small
#    margin before the limit), in small steps along an arc.
# 5. Release the handle and back the hand straight out along its approach axis, with a Pose built from
#    the present gripper pose.
def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def shifted_pose(pose, direction, distance):
    # A copy of pose, moved by distance metres along direction, same orientation.
    d = np.array(direction, dtype=float)
    d = d / np.linalg.norm(d)
    new_pose = Pose()
    new_pose.position.x = pose.position.x + distance * d[0]
    new_pose.position.y = pose.position.y + distance * d[1]
    new_pose.position.z = pose.position.z + distance * d[2]
    new_pose.orientation.x = pose.orientation.x
    new_pose.orientation.y = pose.orientation.y
    new_pose.orientation.z = pose.orientation.z
    new_pose.orientation.w = pose.orientation.w
    return new_pose


detect_objects()
handle_position = get_object_center_position('cabinet.handle_2')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='revolute')
margin = 3.0  # degrees kept short of the joint limit
remaining = joint['joint_upper'] - joint['joint_value'] - margin

if remaining > 1.0:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_2'))
    close_gripper()
    attach_object('cabinet.door_0')
    n_steps = max(10, int(np.ceil(remaining / 3.0)))
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=n_steps, angle=remaining)
    follow_path(path)
    open_gripper()
    detach_object('cabinet.door_0')
    hand = get_gripper_pose()
    move_to_pose(shifted_pose(hand, -approach_axis(hand), 0.08))
