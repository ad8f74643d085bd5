# Task: swap the positions of the green block and the lemon.
# Plan:
# 1. Detect everything and remember both centres before anything moves.
# 2. Move the green block aside to a free spot of the table (parse_place_pose with 'table' keeps its old place
#    free); assert it went at least 10 cm from where it stood.
# 3. Move the lemon to where the green block was; assert it lies within 4 cm of that spot in x, y.
# 4. Move the green block to where the lemon was; assert it lies within 4 cm of that spot in x, y.
#    Both are small enough for a top-down grasp at their middle (block a few cm, lemon about 6 cm, under 8 cm).

SPOT_TOL = 0.04    # m: how far from the other's old centre an object may end up (about half its width)
ASIDE_MIN = 0.10   # m: how far the block must have gone from its place so that the lemon can go there


def fmt(v) -> str:
    """A vector rounded to millimetres, for printing."""
    return str(np.round(np.asarray(v, dtype=float), 3).tolist())


def pose_xyz(pose: Pose) -> np.ndarray:
    """The position of a Pose as an array."""
    return np.array([pose.position.x, pose.position.y, pose.position.z])


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
    where = receptacle if position is None else fmt(position)
    print(f'[place] {name} -> {where}: place pose at {fmt(pose_xyz(place_pose))}')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)
    print(f'[place] {name} released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


def move_object(name: str, receptacle: str = None, position: np.ndarray = None) -> np.ndarray:
    """Pick `name` top-down at its middle and set it down; return its centre, seen anew."""
    pick(name, parse_central_lift_grasp_pose(object_name=name, description='center'))
    place(name, receptacle=receptacle, position=position)
    detect_objects()
    now = get_object_center_position(name)
    print(f'[check] {name} now at {fmt(now)}')
    return now


def xy_distance(a: np.ndarray, b: np.ndarray) -> float:
    """Horizontal distance between two points."""
    return float(np.linalg.norm(np.asarray(a)[:2] - np.asarray(b)[:2]))


print('[start] detecting objects')
detect_objects()
block_at = get_object_center_position('green_block')
lemon_at = get_object_center_position('lemon')
print(f'[start] green_block at {fmt(block_at)}, lemon at {fmt(lemon_at)}')

print('[step 2] moving the green block aside')
aside = move_object('green_block', receptacle='table')
assert xy_distance(aside, block_at) >= ASIDE_MIN, \
    f'the green block is only {xy_distance(aside, block_at):.3f} m from its place, which is not free'

print('[step 3] moving the lemon to where the green block was')
lemon_now = move_object('lemon', position=block_at)
assert xy_distance(lemon_now, block_at) <= SPOT_TOL, \
    f'the lemon is {xy_distance(lemon_now, block_at):.3f} m from the green block\'s old place {fmt(block_at)}'

print('[step 4] moving the green block to where the lemon was')
block_now = move_object('green_block', position=lemon_at)
assert xy_distance(block_now, lemon_at) <= SPOT_TOL, \
    f'the green block is {xy_distance(block_now, lemon_at):.3f} m from the lemon\'s old place {fmt(lemon_at)}'
print('[done] the green block and the lemon have swapped places')
