# Task: close the open drawer.
# Plan:
# 1. The rows from the top are drawer_0 (handle_0), drawer_1 (handle_1) and door_0 (handle_2). Detect everything
#    and read how far each drawer's prismatic joint is open; the open drawer is the one open farthest.
# 2. Assert that one is open at all (more than 1 cm).
# 3. Grasp its handle horizontally, close the fingers, attach the drawer and push it along -joint axis by as far as
#    it is open.
# 4. Let go, detach the drawer and back the hand away 5 cm along +axis.
# 5. Look again and assert that the drawer is now shut to within 1.5 cm.

DRAWERS = {'cabinet.drawer_0': 'cabinet.handle_0', 'cabinet.drawer_1': 'cabinet.handle_1'}
OPEN_MIN = 0.01     # m: a drawer open less than this counts as shut
SHUT_TOL = 0.015    # m: how far open it may still be seen after pushing


def fmt(v) -> str:
    """A vector rounded to millimetres, for printing."""
    return str(np.round(np.asarray(v, dtype=float), 3).tolist())


def pose_xyz(pose: Pose) -> np.ndarray:
    """The position of a Pose as an array."""
    return np.array([pose.position.x, pose.position.y, pose.position.z])


def drawer_joint(drawer: str) -> dict:
    """The drawer's prismatic joint, read near its handle's present centre."""
    handle_at = get_object_center_position(DRAWERS[drawer])
    joint = get_object_joint_info(object_name=drawer, position=handle_at, type='prismatic')
    print(f'[joint] {drawer}: handle at {fmt(handle_at)}; axis {fmt(joint["joint_axis"])}, '
          f'open {joint["joint_value"]:.3f} m of {joint["joint_upper"]:.3f} m')
    return joint


print('[start] detecting objects')
detect_objects()
joints = {drawer: drawer_joint(drawer) for drawer in DRAWERS}
drawer = max(joints, key=lambda d: joints[d]['joint_value'])
joint = joints[drawer]
handle = DRAWERS[drawer]
print(f'[step 1] the open drawer is {drawer}, open {joint["joint_value"]:.3f} m')

print('[step 2] checking that it is open')
assert joint['joint_value'] > OPEN_MIN, f'no drawer is open (the most open, {drawer}, is at {joint["joint_value"]:.3f} m)'

print(f'[step 3] grasping {handle} and pushing {drawer} shut by {joint["joint_value"]:.3f} m')
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object(drawer)
move_in_direction(joint['joint_axis'], -joint['joint_value'])

print('[step 4] letting go and backing away')
open_gripper()
detach_object(drawer)
move_in_direction(joint['joint_axis'], 0.05)
print(f'[step 4] gripper at {fmt(pose_xyz(get_gripper_pose()))}')

print('[step 5] checking the drawer')
detect_objects()
left_open = drawer_joint(drawer)['joint_value']
assert left_open <= SHUT_TOL, f'{drawer} is still open {left_open:.3f} m, more than {SHUT_TOL} m'
print(f'[done] {drawer} is closed')
