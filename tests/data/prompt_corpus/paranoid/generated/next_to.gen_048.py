# Task: place the white mug beside the white bowl.
# Plan:
# 1. Look at the scene; check white_mug and white_bowl are known; measure the table, the bowl and
#    the mug.
# 2. Candidate spots on the table, the mug's centre 3 cm plus half the mug's longer side beyond the
#    bowl's edge: first on the bowl's left or right (the side the mug is on first), then in front
#    of it, then behind it. Keep those on the table, away from the robot's base and clear of every
#    other object's footprint.
# 3. Pick the mug (adaptive grasp from above, else horizontal, else central lift; each checked:
#    the hand reached the grasp pose, attach raises on empty fingers, a new look shows the mug rose
#    with the hand).
# 4. Place it on the first candidate spot (if the place tool refuses or the arm cannot get there,
#    the next spot), check the hand reached the place pose, release, move up.
# 5. Look again: the mug must stand on the table, not in the bowl, within 10 cm of the bowl's
#    edge. If not, pick it again and try the next spot; with none left, give up with a RuntimeError.

MOTION_ERRORS = (GraspError, PlanningError, IKError, FailureError)
ROBOT_BASE_XY = np.array([-0.45, 0.0])


def require_names(*names):
    known = get_object_name_list()
    missing = [name for name in names if name not in known]
    if missing:
        raise RuntimeError('not in the scene: %s' % ', '.join(missing))


def pose_position(pose):
    return np.array([pose.position.x, pose.position.y, pose.position.z], dtype=float)


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def tcp_reached(pose):
    # The arm reaches a commanded pose to within millimetres; a TCP more than 2 cm away from it
    # means the motion stopped somewhere else.
    return np.linalg.norm(pose_position(get_gripper_pose()) - pose_position(pose)) <= 0.02


def try_move(axis, distance):
    # A straight move whose failure the caller handles; returns whether it was done.
    try:
        move_in_direction(axis, distance)
        return True
    except MOTION_ERRORS:
        return False


def back_off():
    # Take the hand back along its approach axis, else straight up.
    if not try_move(-approach_axis(get_gripper_pose()), 0.10):
        try_move([0, 0, 1], 0.10)


def inside_xy(point, box):
    return box[0] <= point[0] <= box[3] and box[1] <= point[1] <= box[4]


def grasp_options(name):
    # Three different grasp tools, the most suitable first; each is tried once.
    central = ('central lift grasp at mid height',
               lambda: parse_central_lift_grasp_pose(object_name=name, description='center'))
    adaptive = ('adaptive grasp from above',
                lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    horizontal = ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name=name))
    if 'mug' in name or 'cup' in name:
        return [adaptive, horizontal, central]
    return [central, adaptive, horizontal]


def held(name, start):
    # Look again. attach_object lifts the object 5 cm and we lifted 10 cm more, so a held object
    # rose about 15 cm; 3 cm is well above the detection noise (about 1 cm) and well below 15 cm,
    # while an object left behind rose by about 0. It must also be at the fingers: its centre no
    # farther from the TCP than half its box diagonal (the farthest point of its box) plus 3 cm.
    detect_objects(object_list=[name])
    center = get_object_center_position(name)
    box = get_3d_bbox(name)
    reach = 0.5 * np.linalg.norm(box[3:] - box[:3]) + 0.03
    tcp = pose_position(get_gripper_pose())
    return center[2] - start[2] >= 0.03 and np.linalg.norm(center - tcp) <= reach


def pick(name, options=None, lift=0.10):
    failures = []
    for label, make_grasp in (options or grasp_options(name)):
        detect_objects(object_list=[name])  # fresh view: a failed try may have nudged it
        start = get_object_center_position(name)
        open_gripper()
        try:
            grasp_pose = make_grasp()
        except MOTION_ERRORS as error:
            failures.append('%s: %s' % (label, error))
            continue
        try:
            grasp(grasp_pose)
        except MOTION_ERRORS as error:
            failures.append('%s: %s' % (label, error))
            back_off()
            continue
        if not tcp_reached(grasp_pose):
            failures.append('%s: the hand stopped short of the grasp pose' % label)
            back_off()
            continue
        close_gripper()
        try:
            attach_object(name)  # GraspError where the fingers closed on nothing
        except MOTION_ERRORS as error:
            failures.append('%s: %s' % (label, error))
            open_gripper()
            back_off()
            continue
        if try_move([0, 0, 1], lift):
            lifted = lift
        elif try_move([0, 0, 1], lift / 2):
            lifted = lift / 2
        else:
            lifted = 0.0
        if held(name, start):
            return
        failures.append('%s: %s was not in the hand after lifting' % (label, name))
        if lifted > 0:
            try_move([0, 0, -1], lifted)  # go back down before letting go, so nothing is dropped
        open_gripper()
        detach_object(name)
        try_move([0, 0, 1], 0.10)
    raise RuntimeError('could not pick up %s (%s)' % (name, '; '.join(failures)))


def place(name, receptacle=None, position=None):
    # Two tries: if the arm cannot get there, rise 5 cm (a slightly different start) and ask
    # again. No room at all is final. Every RuntimeError here leaves the object in the hand.
    failures = []
    for attempt in range(2):
        try:
            place_pose = parse_place_pose(object_name=name, receptacle_name=receptacle, position=position)
            move_to_pose(place_pose)
        except (PlanningError, IKError) as error:
            failures.append(str(error))
            try_move([0, 0, 1], 0.05)
            continue
        except (PlacementError, ReceptacleFullError, CompartmentError) as error:
            raise RuntimeError('no place for %s: %s' % (name, error))
        if not tcp_reached(place_pose):
            raise RuntimeError('the hand did not reach the place pose for %s' % name)
        open_gripper()
        detach_object(name)
        if not try_move([0, 0, 1], 0.10):
            back_off()
        return
    raise RuntimeError('could not carry %s to its place (%s)' % (name, '; '.join(failures)))


detect_objects()
require_names('white_mug', 'white_bowl', 'table')

table_box = get_3d_bbox('table')
table_top = table_box[5]
bowl_box = get_3d_bbox('white_bowl')
bowl_center = get_object_center_position('white_bowl')
mug_box = get_3d_bbox('white_mug')
mug_center = get_object_center_position('white_mug')
# The mug may turn on the way: take half its longer side as the half-width of its footprint.
mug_half = 0.5 * max(mug_box[3] - mug_box[0], mug_box[4] - mug_box[1])
GAP = 0.03  # 3 cm between the bowl's edge and the mug's: clearly beside it, yet not touching

spots = {
    'left of': np.array([bowl_center[0], bowl_box[4] + GAP + mug_half]),
    'right of': np.array([bowl_center[0], bowl_box[1] - GAP - mug_half]),
    'in front of': np.array([bowl_box[0] - GAP - mug_half, bowl_center[1]]),
    'behind': np.array([bowl_box[3] + GAP + mug_half, bowl_center[1]]),
}
order = ['left of', 'right of'] if mug_center[1] >= bowl_center[1] else ['right of', 'left of']
order += ['in front of', 'behind']
others = [name for name in get_object_name_list()
          if name not in ('table', 'white_bowl', 'white_mug') and not name.startswith('cabinet')]


def spot_is_free(xy):
    # The mug's whole footprint on the table (1 cm inside its edge).
    if not (table_box[0] + mug_half + 0.01 <= xy[0] <= table_box[3] - mug_half - 0.01
            and table_box[1] + mug_half + 0.01 <= xy[1] <= table_box[4] - mug_half - 0.01):
        return False
    # At least 25 cm from the robot's base: the place tool refuses within 20 cm, 5 cm margin.
    if np.linalg.norm(xy - ROBOT_BASE_XY) < 0.25:
        return False
    # No other object's footprint within 1 cm of the mug's.
    for other in others:
        box = get_3d_bbox(other)
        if (box[0] - 0.01 < xy[0] + mug_half and xy[0] - mug_half < box[3] + 0.01
                and box[1] - 0.01 < xy[1] + mug_half and xy[1] - mug_half < box[4] + 0.01):
            return False
    return True


def mug_beside_bowl():
    # Beside: standing on the table (its bottom within 2 cm of the table top: detection noise),
    # its centre not over the bowl (not in it), and its edge within 10 cm of the bowl's edge
    # (3 cm planned, up to 7 cm more where the place tool had to shift it).
    detect_objects(object_list=['white_mug', 'white_bowl'])
    mug = get_3d_bbox('white_mug')
    bowl = get_3d_bbox('white_bowl')
    center = get_object_center_position('white_mug')
    dx = max(bowl[0] - mug[3], mug[0] - bowl[3], 0.0)
    dy = max(bowl[1] - mug[4], mug[1] - bowl[4], 0.0)
    edge_gap = float(np.hypot(dx, dy))
    return abs(mug[2] - table_top) <= 0.02 and not inside_xy(center, bowl) and edge_gap <= 0.10


free = [side for side in order if spot_is_free(spots[side])]
if not free:
    raise RuntimeError('no free spot on the table beside the white bowl')

holding = False
for side in free:
    if not holding:
        pick('white_mug')
        holding = True
    xy = spots[side]
    try:
        place('white_mug', position=[xy[0], xy[1], table_top])
    except RuntimeError as error:
        print('could not set the mug down %s the bowl: %s' % (side, error))
        continue  # still holding it: try the next spot
    holding = False
    if mug_beside_bowl():
        break
    print('the mug did not end up beside the bowl (%s); trying another spot' % side)
else:
    raise RuntimeError('could not place the white mug beside the white bowl')
