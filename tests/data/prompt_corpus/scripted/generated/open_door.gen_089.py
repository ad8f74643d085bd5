# Task: swing the cabinet door open.
# Plan:
# 1. Detect everything. The cabinet has, from the top, door_0 (handle_0) and drawer_0 (handle_1).
# 2. Read the door's revolute joint near its handle; aim for the target angle, capped at the joint's limit.
# 3. Open the gripper, grasp handle_0 horizontally, close the gripper and attach the door.
# 4. Follow an arc about the hinge from the present gripper pose, in small steps (a positive angle opens).
# 5. Open the gripper, detach the door and back the hand out along its approach axis.
# 6. Look again and report how far the door is open.

DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'
TARGET_DOOR_ANGLE_DEG = 90.0
ARC_STEP_DEG = 3.0
HAND_BACK_OFF_M = 0.08


def approach_axis(pose: Pose) -> np.ndarray:
    """The gripper's approach (z) axis, from the pose's quaternion."""
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def door_joint() -> dict:
    """The door's revolute joint, found near its handle."""
    handle_center = get_object_center_position(HANDLE)
    return get_object_joint_info(object_name=DOOR, position=handle_center, type='revolute')


def open_door() -> None:
    """Grasp the handle and swing the door open towards the target angle."""
    joint = door_joint()
    target = min(TARGET_DOOR_ANGLE_DEG, float(joint['joint_upper']))
    angle = target - float(joint['joint_value'])
    print(f'Door is open {joint["joint_value"]:.0f} deg; swinging it {angle:.0f} deg more')
    if angle <= 0:
        print('The door is already open; nothing to do')
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=HANDLE))
    close_gripper()
    attach_object(DOOR)
    steps = max(10, int(angle / ARC_STEP_DEG))
    path = generate_arc_path_around_joint(
        current_pose=get_gripper_pose(),
        joint_axis=joint['joint_axis'],
        joint_position=joint['joint_position'],
        n=steps,
        angle=angle,
    )
    follow_path(path)
    open_gripper()
    detach_object(DOOR)
    move_in_direction(-approach_axis(get_gripper_pose()), HAND_BACK_OFF_M)


def main() -> None:
    """Open the cabinet door."""
    detect_objects()
    open_door()
    detect_objects([DOOR, HANDLE])
    print(f'Done: {DOOR} is open {door_joint()["joint_value"]:.0f} deg')


if __name__ == "__main__":
    main()
