# Task: swing the cabinet door open.
# Plan:
# 1. The cabinet has two drawers above one door: the door is cabinet.door_0, its handle cabinet.handle_2
#    (third row from the top).
# 2. Read the door's revolute joint near the handle: its present opening and its limit, in degrees.
# 3. Aim for a clearly open door, about 80 degrees, but never past the joint's limit; turn only by what
#    is still missing.
# 4. Grasp the handle horizontally, attach the door, follow an arc about the hinge in small steps.
# 5. Release the handle and back the hand out along its approach axis with a Pose built from the
#    present gripper pose.
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
target_angle = min(80.0, joint['joint_upper'] - 2.0)  # degrees, kept just short of the limit
turn = target_angle - joint['joint_value']

if turn > 1.0:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_2'))
    close_gripper()
    attach_object('cabinet.door_0')
    n_steps = max(10, int(np.ceil(turn / 3.0)))
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=n_steps, angle=turn)
    follow_path(path)
    open_gripper()
    detach_object('cabinet.door_0')
    hand = get_gripper_pose()
    move_to_pose(shifted_pose(hand, -approach_axis(hand), 0.08))
