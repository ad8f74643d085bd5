# Task: open the cabinet door, then place the blue box inside the cabinet.
# Plan:
# 1. The query lists the door first, so it is the top row: its handle is cabinet.handle_0 (cabinet.handle_1 is the
#    drawer's below it). Detect everything; remember the shut cabinet's box and the door's height range (the
#    compartment behind it) and read the door's revolute joint near its handle.
# 2. Open the door to 90 degrees (or its limit): grasp the handle horizontally, attach the door, follow an arc about
#    the hinge by the angle still missing, let go and back the hand out 8 cm along its approach axis.
# 3. Look again and assert that the swing turned it at least 5 degrees; where it stopped short of 75 degrees swing
#    again (at most 3 swings). Then assert that it is open at least 45 degrees (placing needs 40, plus 5 to spare).
# 4. Grasp the blue box level (parse_horizontal_grasp_pose, as placing behind a door demands), attach it, lift it
#    5 cm more.
# 5. Get the place pose into the compartment behind cabinet.door_0, move there, open the fingers (the hand backs
#    out the way it came), detach the box and back off 5 cm more along the approach axis.
# 6. Look again and assert that the box's centre is within the shut cabinet's box in x, y and within the door's
#    height range in z.

DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'
AIM_DEG = 90.0       # degrees: open the door well past what placing needs
RETRY_BELOW = 75.0   # degrees: swing again where the door stopped short of this
PLACE_MIN = 45.0     # degrees: parse_place_pose needs 40; 5 to spare
MIN_SWING = 5.0      # degrees: the least a swing must turn the door
MAX_SWINGS = 3
MARGIN = 0.01        # m: perception noise allowed at the edges of a box


def fmt(v) -> str:
    """A vector rounded to millimetres, for printing."""
    return str(np.round(np.asarray(v, dtype=float), 3).tolist())


def pose_xyz(pose: Pose) -> np.ndarray:
    """The position of a Pose as an array."""
    return np.array([pose.position.x, pose.position.y, pose.position.z])


def approach_axis(pose: Pose) -> np.ndarray:
    """The gripper's approach (z) axis from its quaternion."""
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def door_joint() -> dict:
    """The door's revolute joint, read near its handle's present centre."""
    handle_at = get_object_center_position(HANDLE)
    joint = get_object_joint_info(object_name=DOOR, position=handle_at, type='revolute')
    print(f'[joint] handle at {fmt(handle_at)}; hinge through {fmt(joint["joint_position"])} along '
          f'{fmt(joint["joint_axis"])}; open {joint["joint_value"]:.1f} of {joint["joint_upper"]:.1f} degrees')
    return joint


def swing_door(joint: dict, angle: float) -> None:
    """Grasp the handle, attach the door, turn it `angle` degrees about its hinge, let go and back out."""
    print(f'[door] grasping {HANDLE} to swing {DOOR} by {angle:.1f} degrees')
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=HANDLE))
    close_gripper()
    attach_object(DOOR)
    n = max(10, int(np.ceil(angle / 3.0)))
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                          joint_position=joint['joint_position'], n=n, angle=angle)
    follow_path(path)
    open_gripper()
    detach_object(DOOR)
    move_in_direction(-approach_axis(get_gripper_pose()), 0.08)
    print(f'[door] released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


print('[start] detecting objects')
detect_objects()
cabinet_box = get_3d_bbox('cabinet')
door_box = get_3d_bbox(DOOR)
print(f'[start] cabinet box {fmt(cabinet_box)}, door box {fmt(door_box)}, blue_box box {fmt(get_3d_bbox("blue_box"))}')
joint = door_joint()
aim = min(AIM_DEG, joint['joint_upper'])

for swing in range(MAX_SWINGS):
    before = joint['joint_value']
    if before >= min(RETRY_BELOW, aim):
        break
    print(f'[step 2] swing {swing + 1}: the door is at {before:.1f} degrees, aiming at {aim:.1f}')
    swing_door(joint, aim - before)
    print('[step 3] checking the door')
    detect_objects()
    joint = door_joint()
    assert joint['joint_value'] >= before + MIN_SWING, \
        f'swing {swing + 1} moved {DOOR} from {before:.1f} to only {joint["joint_value"]:.1f} degrees'
assert joint['joint_value'] >= PLACE_MIN, \
    f'{DOOR} is open {joint["joint_value"]:.1f} degrees, placing behind it needs at least {PLACE_MIN}'

print('[step 4] picking the blue box with a level grasp')
box_grasp = parse_horizontal_grasp_pose(object_name='blue_box')
print(f'[step 4] blue_box centre {fmt(get_object_center_position("blue_box"))}, grasp at {fmt(pose_xyz(box_grasp))}')
open_gripper()
grasp(box_grasp)
close_gripper()
attach_object('blue_box')
move_in_direction([0, 0, 1], 0.05)
print(f'[step 4] blue_box held; gripper at {fmt(pose_xyz(get_gripper_pose()))}')

print('[step 5] placing the blue box into the cabinet behind the door')
place_pose = parse_place_pose(object_name='blue_box', receptacle_name=DOOR)
print(f'[step 5] place pose at {fmt(pose_xyz(place_pose))}')
move_to_pose(place_pose)
open_gripper()
detach_object('blue_box')
move_in_direction(-approach_axis(get_gripper_pose()), 0.05)
print(f'[step 5] released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')

print('[step 6] checking the blue box')
detect_objects()
c = get_object_center_position('blue_box')
print(f'[check] blue_box centre {fmt(c)}; shut cabinet box {fmt(cabinet_box)}; door z {door_box[2]:.3f}..{door_box[5]:.3f}')
assert cabinet_box[0] - MARGIN <= c[0] <= cabinet_box[3] + MARGIN and \
    cabinet_box[1] - MARGIN <= c[1] <= cabinet_box[4] + MARGIN, \
    f'blue_box centre {fmt(c)} is not within the cabinet box {fmt(cabinet_box)} in x, y'
assert door_box[2] - MARGIN <= c[2] <= door_box[5] + MARGIN, \
    f'blue_box centre height {c[2]:.3f} is outside the compartment {door_box[2]:.3f}..{door_box[5]:.3f}'
print('[done] the cabinet door is open and the blue box is inside the cabinet')
