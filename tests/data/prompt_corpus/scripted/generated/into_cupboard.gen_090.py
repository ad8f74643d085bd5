# Task: open the cabinet door and put the rubiks cube in the cupboard behind it.
# Plan:
# 1. Detect everything. The cabinet has, from the top, door_0 (handle_0) and drawer_0 (handle_1).
# 2. Open the gripper, grasp the door's handle horizontally, close the gripper and attach the door.
# 3. Read the door's revolute joint near the handle and swing the hand along an arc about the hinge up to
#    the target angle (capped at the joint's limit).
# 4. Open the gripper, detach the door and back the hand out along its approach axis.
# 5. Look again and check the door is open at least 40 degrees (needed to place into the compartment).
# 6. Grasp the cube with a horizontal grasp (the object must be carried in level), close, attach, lift.
# 7. Get the place pose into the compartment behind cabinet.door_0, move there, open the gripper and
#    detach the cube (the hand backs out the way it came).

DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'
OBJECT = 'rubiks_cube'
TARGET_DOOR_ANGLE_DEG = 90.0
MIN_DOOR_ANGLE_DEG = 40.0
ARC_STEP_DEG = 3.0
HAND_BACK_OFF_M = 0.08
LIFT_HEIGHT_M = 0.05
UP = [0, 0, 1]


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
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=HANDLE))
    close_gripper()
    attach_object(DOOR)
    if angle > 0:
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


def check_door_open() -> None:
    """Look again and make sure the door is open wide enough to reach the compartment."""
    detect_objects([DOOR, HANDLE])
    opening = float(door_joint()['joint_value'])
    print(f'Door is now open {opening:.0f} deg')
    if opening < MIN_DOOR_ANGLE_DEG:
        raise FailureError(f'the door opened only {opening:.0f} degrees; {MIN_DOOR_ANGLE_DEG:.0f} are needed')


def pick_level(name: str) -> None:
    """Grasp the object with a level (horizontal) grasp, attach it and lift it."""
    print(f'Picking {name} with a horizontal grasp')
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name))
    close_gripper()
    attach_object(name)
    move_in_direction(UP, LIFT_HEIGHT_M)


def place_in_cupboard(name: str) -> None:
    """Carry the held object into the compartment behind the door and let go."""
    print(f'Placing {name} into the compartment behind {DOOR}')
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=DOOR))
    open_gripper()
    detach_object(name)


def main() -> None:
    """Open the door, then put the cube in the cupboard."""
    detect_objects()
    open_door()
    check_door_open()
    pick_level(OBJECT)
    place_in_cupboard(OBJECT)
    print(f'Done: {OBJECT} is in the cupboard')


if __name__ == "__main__":
    main()
