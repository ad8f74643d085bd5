# Task: open the top drawer of the cabinet and put the red cup into it.
# Plan:
# 1. The cabinet has three drawers; the top one is cabinet.drawer_0 and its handle cabinet.handle_0.
#    Detect everything and read the drawer's prismatic joint near the handle (how far it is open, how far it can).
# 2. Grasp the handle horizontally, close the fingers, attach the drawer and pull it along +joint axis until it is
#    open 20 cm (or as far as it goes); let go and back away 5 cm along the axis.
# 3. Look again and assert that the drawer is now open to within 4 cm of that target.
# 4. Grasp the red cup from above by its rim (adaptive grasp, which also takes cups wider than the opening), attach
#    it and lift it 10 cm.
# 5. Get a place pose inside the open drawer, move there, let go, detach and move up.
# 6. Look again and assert that the cup's centre is within the drawer's box in x, y and its bottom below the
#    drawer's top (it is inside the drawer).

DRAWER = 'cabinet.drawer_0'
HANDLE = 'cabinet.handle_0'
OPEN_TO = 0.2     # m: how far to open the drawer, enough room for a cup
OPEN_TOL = 0.04   # m: the drawer may lag the hand by this much (slip on the handle)
MARGIN = 0.01     # m: perception noise allowed at the edges of a box


def fmt(v) -> str:
    """A vector rounded to millimetres, for printing."""
    return str(np.round(np.asarray(v, dtype=float), 3).tolist())


def pose_xyz(pose: Pose) -> np.ndarray:
    """The position of a Pose as an array."""
    return np.array([pose.position.x, pose.position.y, pose.position.z])


def drawer_joint() -> dict:
    """The drawer's prismatic joint, read near its handle's present centre."""
    handle_at = get_object_center_position(HANDLE)
    joint = get_object_joint_info(object_name=DRAWER, position=handle_at, type='prismatic')
    print(f'[joint] handle at {fmt(handle_at)}; axis {fmt(joint["joint_axis"])}, '
          f'open {joint["joint_value"]:.3f} m of {joint["joint_upper"]:.3f} m')
    return joint


def pull_drawer(joint: dict, distance: float) -> None:
    """Grasp the handle, attach the drawer, move `distance` m along its axis, let go and back away."""
    print(f'[drawer] grasping {HANDLE} to pull {DRAWER} by {distance:.3f} m')
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=HANDLE))
    close_gripper()
    attach_object(DRAWER)
    move_in_direction(joint['joint_axis'], distance)
    open_gripper()
    detach_object(DRAWER)
    move_in_direction(joint['joint_axis'], 0.05)
    print(f'[drawer] released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


def pick(name: str, grasp_pose: Pose, lift: float = 0.1) -> None:
    """Grasp `name` at `grasp_pose`, close the fingers, attach it and lift it by `lift` metres."""
    print(f'[pick] {name}: centre {fmt(get_object_center_position(name))}, box {fmt(get_3d_bbox(name))}, '
          f'grasp at {fmt(pose_xyz(grasp_pose))}')
    open_gripper()
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)
    print(f'[pick] {name} held; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


def place(name: str, receptacle: str = None, position: np.ndarray = None, retreat: float = 0.1) -> None:
    """Set the held `name` down in or on `receptacle` (and/or at `position`), let go and move up."""
    place_pose = parse_place_pose(object_name=name, receptacle_name=receptacle, position=position)
    print(f'[place] {name} -> {receptacle}: place pose at {fmt(pose_xyz(place_pose))}')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)
    print(f'[place] {name} released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


print('[start] detecting objects')
detect_objects()
joint = drawer_joint()
target_open = min(OPEN_TO, joint['joint_upper'])

print(f'[step 2] opening {DRAWER} to {target_open:.3f} m')
if target_open - joint['joint_value'] > 0.01:
    pull_drawer(joint, target_open - joint['joint_value'])
else:
    print('[step 2] the drawer is already open far enough')

print('[step 3] checking the drawer')
detect_objects()
opened = drawer_joint()['joint_value']
assert opened >= target_open - OPEN_TOL, \
    f'{DRAWER} is open {opened:.3f} m, wanted at least {target_open - OPEN_TOL:.3f} m'

print('[step 4] picking the red cup from above by its rim')
pick('red_cup', parse_adaptive_shape_grasp_pose(object_name='red_cup', preferred_approach_direction=[0, 0, -1]))

print(f'[step 5] placing the red cup into {DRAWER}')
place('red_cup', receptacle=DRAWER)

print('[step 6] checking the cup')
detect_objects()
cup_c = get_object_center_position('red_cup')
cup_b = get_3d_bbox('red_cup')
drawer_b = get_3d_bbox(DRAWER)
print(f'[check] red_cup centre {fmt(cup_c)}, box {fmt(cup_b)}; {DRAWER} box {fmt(drawer_b)}')
assert drawer_b[0] - MARGIN <= cup_c[0] <= drawer_b[3] + MARGIN and \
    drawer_b[1] - MARGIN <= cup_c[1] <= drawer_b[4] + MARGIN, \
    f'red_cup centre {fmt(cup_c)} is not within {DRAWER} box {fmt(drawer_b)} in x, y'
assert cup_b[2] < drawer_b[5], f'red_cup bottom {cup_b[2]:.3f} is not below the drawer top {drawer_b[5]:.3f}'
print('[done] the top drawer is open and the red cup is in it')
