# Task: put the rubiks cube into the green bowl.
# Plan:
# 1. Detect everything and measure the rubiks cube and the green bowl.
# 2. Grasp the cube top-down at its middle (a Rubik's cube is about 5.7 cm, narrower than the 8 cm opening),
#    close the fingers, attach it and lift it 10 cm.
# 3. Get a place pose inside the green bowl, move there, open the fingers, detach the cube and move up 10 cm.
# 4. Look again and assert that the cube's centre lies within the bowl's box in x and y and that its bottom is
#    below the bowl's rim (it is in the bowl, not balanced on its edge).

MARGIN = 0.01  # m: perception noise allowed at the edges of a box


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
    print(f'[place] {name} -> {receptacle}: place pose at {fmt(pose_xyz(place_pose))}')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)
    print(f'[place] {name} released; gripper at {fmt(pose_xyz(get_gripper_pose()))}')


def assert_in(name: str, receptacle: str) -> None:
    """Look again; assert that `name`'s centre is within `receptacle`'s box in x, y and below its rim."""
    detect_objects()
    c = get_object_center_position(name)
    b = get_3d_bbox(name)
    r = get_3d_bbox(receptacle)
    print(f'[check] {name} centre {fmt(c)}, box {fmt(b)}; {receptacle} box {fmt(r)}')
    assert r[0] - MARGIN <= c[0] <= r[3] + MARGIN and r[1] - MARGIN <= c[1] <= r[4] + MARGIN, \
        f'{name} centre {fmt(c)} is not within {receptacle} box {fmt(r)} in x, y'
    assert b[2] < r[5], f'{name} bottom {b[2]:.3f} is not below the rim of {receptacle} ({r[5]:.3f})'


print('[start] detecting objects')
detect_objects()
print(f'[start] rubiks_cube box {fmt(get_3d_bbox("rubiks_cube"))}, green_bowl box {fmt(get_3d_bbox("green_bowl"))}')

print('[step 2] picking the rubiks cube from above')
pick('rubiks_cube', parse_central_lift_grasp_pose(object_name='rubiks_cube', description='center'))

print('[step 3] placing the rubiks cube into the green bowl')
place('rubiks_cube', receptacle='green_bowl')

print('[step 4] checking the result')
assert_in('rubiks_cube', 'green_bowl')
print('[done] the rubiks cube is in the green bowl')
