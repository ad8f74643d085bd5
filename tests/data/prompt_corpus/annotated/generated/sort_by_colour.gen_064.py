# Task: sort the objects on the table by colour: put the green objects into the green bowl.
# Plan:
# 1. Detect everything. Colours are known only from names, so the green objects are those whose name starts with
#    'green_', leaving out the green bowl itself, other receptacles that stay put and the furniture: here
#    green_block.
# 2. For each: choose the grasp from the doc-strings (a mug or cup from above by its rim with the adaptive grasp;
#    anything narrower than 7.5 cm top-down at its middle; anything wider adaptive from above), pick it, lift it
#    10 cm, place it into the green bowl, let go, detach and move up.
# 3. After each placement look again and assert that its centre is within the bowl's box in x and y.

BOWL = 'green_bowl'
KEEP = ('table', 'cabinet', 'basket', 'plate', 'bowl', 'saucer')   # name parts of things that stay where they are
FITS = 0.075    # m: narrower than the 8 cm opening (Panda; 8.5 cm on the UR5e) with 5 mm to spare
MARGIN = 0.01   # m: perception noise allowed at the edges of a box


def fmt(v) -> str:
    """A vector rounded to millimetres, for printing."""
    return str(np.round(np.asarray(v, dtype=float), 3).tolist())


def pose_xyz(pose: Pose) -> np.ndarray:
    """The position of a Pose as an array."""
    return np.array([pose.position.x, pose.position.y, pose.position.z])


def grasp_pose_for(name: str) -> Pose:
    """A grasp chosen by what the object is and how wide it is."""
    b = get_3d_bbox(name)
    narrow = min(b[3] - b[0], b[4] - b[1])
    if 'mug' in name or 'cup' in name:
        print(f'[grasp] {name}: a mug or cup, adaptive grasp by its rim from above')
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    if narrow < FITS:
        print(f'[grasp] {name}: {narrow:.3f} m across, central lift grasp')
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    print(f'[grasp] {name}: {narrow:.3f} m across, wider than the opening, adaptive grasp from above')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


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


def assert_inside_xy(name: str, receptacle: str) -> None:
    """Look again; assert that `name`'s centre is within `receptacle`'s box in x and y."""
    detect_objects()
    c = get_object_center_position(name)
    r = get_3d_bbox(receptacle)
    print(f'[check] {name} centre {fmt(c)}; {receptacle} box {fmt(r)}')
    assert r[0] - MARGIN <= c[0] <= r[3] + MARGIN and r[1] - MARGIN <= c[1] <= r[4] + MARGIN, \
        f'{name} centre {fmt(c)} is not within the {receptacle} box {fmt(r)} in x, y'


print('[start] detecting objects')
detect_objects()
green = [name for name in get_object_name_list()
         if name.startswith('green_') and not any(part in name for part in KEEP)]
print(f'[step 1] green objects to sort: {green}; {BOWL} box {fmt(get_3d_bbox(BOWL))}')

for name in green:
    print(f'[step 2] moving {name} into {BOWL}')
    pick(name, grasp_pose_for(name))
    place(name, receptacle=BOWL)
    print(f'[step 3] checking {name}')
    assert_inside_xy(name, BOWL)
print(f'[done] {len(green)} green objects are in {BOWL}')
