# Task: put the wooden block on the brown box.
# Plan:
# 1. Detect everything; measure the wooden block and the brown box.
# 2. Grasp the block top-down at its middle (a block is narrower than the 8 cm opening), attach it and lift it
#    15 cm, higher than the box.
# 3. Get a place pose on top of the brown box (stacking on its flat top), move there, let go, detach, move up.
# 4. Look again and assert that the block's centre is within the box's box in x, y and that the block's bottom is
#    within 1.5 cm of the box's top (it rests on it, not beside it).

MARGIN = 0.01      # m: perception noise allowed at the edges of a box
REST_TOL = 0.015   # m: how far the block's bottom may be seen from the box's top


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
print(f'[start] wooden_block box {fmt(get_3d_bbox("wooden_block"))}, brown_box box {fmt(get_3d_bbox("brown_box"))}')

print('[step 2] picking the wooden block from above')
pick('wooden_block', parse_central_lift_grasp_pose(object_name='wooden_block', description='center'), lift=0.15)

print('[step 3] placing the wooden block on the brown box')
place('wooden_block', receptacle='brown_box')

print('[step 4] checking the result')
detect_objects()
block_c = get_object_center_position('wooden_block')
block_b = get_3d_bbox('wooden_block')
box_b = get_3d_bbox('brown_box')
print(f'[check] wooden_block centre {fmt(block_c)}, box {fmt(block_b)}; brown_box box {fmt(box_b)}')
assert box_b[0] - MARGIN <= block_c[0] <= box_b[3] + MARGIN and \
    box_b[1] - MARGIN <= block_c[1] <= box_b[4] + MARGIN, \
    f'wooden_block centre {fmt(block_c)} is not within the brown_box box {fmt(box_b)} in x, y'
assert abs(block_b[2] - box_b[5]) <= REST_TOL, \
    f'wooden_block bottom {block_b[2]:.3f} is not at the brown_box top {box_b[5]:.3f} (tolerance {REST_TOL} m)'
print('[done] the wooden block is on the brown box')
