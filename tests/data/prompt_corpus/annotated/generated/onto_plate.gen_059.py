# Task: put the blue mug on the blue plate.
# Plan:
# 1. Detect everything; measure the blue mug and the blue plate.
# 2. Grasp the mug from above by its rim (adaptive grasp, which takes mugs wider than the opening), attach it and
#    lift it 10 cm.
# 3. Get a place pose on the blue plate, move there, let go, detach and move up 10 cm.
# 4. Look again and assert that the mug's centre is within the plate's box in x, y and that its bottom is at most
#    2 cm above the plate's top (it rests on the plate, not on something else).

MARGIN = 0.01      # m: perception noise allowed at the edges of a box
REST_TOL = 0.02    # m: how far above the plate top the mug's bottom may be seen


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


print('[start] detecting objects')
detect_objects()
print(f'[start] blue_mug box {fmt(get_3d_bbox("blue_mug"))}, blue_plate box {fmt(get_3d_bbox("blue_plate"))}')

print('[step 2] picking the blue mug from above by its rim')
pick('blue_mug', parse_adaptive_shape_grasp_pose(object_name='blue_mug', preferred_approach_direction=[0, 0, -1]))

print('[step 3] placing the blue mug on the blue plate')
place('blue_mug', receptacle='blue_plate')

print('[step 4] checking the result')
detect_objects()
mug_c = get_object_center_position('blue_mug')
mug_b = get_3d_bbox('blue_mug')
plate_b = get_3d_bbox('blue_plate')
print(f'[check] blue_mug centre {fmt(mug_c)}, box {fmt(mug_b)}; blue_plate box {fmt(plate_b)}')
assert plate_b[0] - MARGIN <= mug_c[0] <= plate_b[3] + MARGIN and \
    plate_b[1] - MARGIN <= mug_c[1] <= plate_b[4] + MARGIN, \
    f'blue_mug centre {fmt(mug_c)} is not within the blue_plate box {fmt(plate_b)} in x, y'
assert mug_b[2] <= plate_b[5] + REST_TOL, \
    f'blue_mug bottom {mug_b[2]:.3f} is more than {REST_TOL} m above the plate top {plate_b[5]:.3f}'
print('[done] the blue mug is on the blue plate')
