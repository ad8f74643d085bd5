# Task: put the white porcelain mug next to the brown cup.
# Plan:
# 1. Detect everything; measure the brown cup, the mug and the table top.
# 2. Choose the spot beside the cup on the side (left, +y, or right, -y) where the mug already is, so that it need
#    not pass over the cup: the cup's centre moved along y by half the cup's width, half the mug's largest width
#    (its handle included) and a 3 cm gap.
# 3. Grasp the mug from above by its rim (adaptive grasp, as for mugs), attach it and lift it 10 cm.
# 4. Place it at that spot on the table, let go, detach and move up.
# 5. Look again and assert that the mug stands beside the cup: centres at most 20 cm apart in x, y, and the mug's
#    bottom below the cup's middle (it stands on the table, not on the cup).

GAP = 0.03        # m: clearance between the mug and the cup
NEXT_TO = 0.20    # m: largest centre-to-centre distance that still reads as "next to"


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


print('[start] detecting objects')
detect_objects()
table_top = get_3d_bbox('table')[5]
cup_c = get_object_center_position('brown_cup')
cup_b = get_3d_bbox('brown_cup')
mug_c = get_object_center_position('white_porcelain_mug')
mug_b = get_3d_bbox('white_porcelain_mug')
print(f'[start] table top {table_top:.3f}; brown_cup centre {fmt(cup_c)}, box {fmt(cup_b)}; '
      f'mug centre {fmt(mug_c)}, box {fmt(mug_b)}')

print('[step 2] choosing the spot beside the cup')
side = 1.0 if mug_c[1] >= cup_c[1] else -1.0   # +1: left of the cup (+y), -1: right of it
mug_half = max(mug_b[3] - mug_b[0], mug_b[4] - mug_b[1]) / 2
offset = (cup_b[4] - cup_b[1]) / 2 + mug_half + GAP
target = np.array([cup_c[0], cup_c[1] + side * offset, table_top])
print(f'[step 2] side {"left" if side > 0 else "right"}, offset {offset:.3f} m, target {fmt(target)}')

print('[step 3] picking the mug from above by its rim')
pick('white_porcelain_mug',
     parse_adaptive_shape_grasp_pose(object_name='white_porcelain_mug', preferred_approach_direction=[0, 0, -1]))

print('[step 4] placing the mug beside the brown cup')
place('white_porcelain_mug', position=target)

print('[step 5] checking the result')
detect_objects()
mug_c = get_object_center_position('white_porcelain_mug')
mug_b = get_3d_bbox('white_porcelain_mug')
cup_c = get_object_center_position('brown_cup')
distance = float(np.linalg.norm(mug_c[:2] - cup_c[:2]))
print(f'[check] mug centre {fmt(mug_c)}, box {fmt(mug_b)}; cup centre {fmt(cup_c)}; distance {distance:.3f} m')
assert distance <= NEXT_TO, f'the mug is {distance:.3f} m from the cup, more than {NEXT_TO} m: not next to it'
assert mug_b[2] < cup_c[2], f'the mug bottom {mug_b[2]:.3f} is not below the cup middle {cup_c[2]:.3f}: is it on it?'
print('[done] the white porcelain mug stands next to the brown cup')
