# Task: put the blue cup next to the soup can.
# Plan:
# 1. Detect everything and check blue_cup and soup_can exist; if the cup already stands within 5 cm of the
#    can, nothing is to be done.
# 2. Compute the target: candidate spots just outside the can's bounding box on its left (+y), right (-y),
#    front (-x) and back (+x), 3 cm gap, using the cup's own half sizes; keep those on the table top,
#    30-75 cm from the base and clear of every other object's box (basket and bowl included); step 3 cm
#    further out if none is free; take the one nearest the cup.
# 3. Pick the cup (adaptive grasp by its rim from above, retry with a horizontal grasp).
# 4. Place it at the target, release, move up.
# 5. Re-detect and verify the gap between the cup's and the can's boxes is 0-10 cm; else RuntimeError.
MOVER = 'blue_cup'
ANCHOR = 'soup_can'

# ---------- helpers ----------
ROBOT_ERRORS = (FailureError, GraspError, PlacementError, PlanningError, IKError, TrackingError)
FIXED_KINDS = ('plate', 'saucer', 'bowl', 'basket')
UP = np.array([0.0, 0.0, 1.0])


def is_furniture(name):
    return name == 'table' or name == 'cabinet' or name.startswith('cabinet.')


def is_fixed(name):
    # Furniture, plates, saucers, bowls and baskets stay where they are: the gripper cannot pick them up.
    return is_furniture(name) or any(kind in name for kind in FIXED_KINDS)


def require_names(names):
    known = get_object_name_list()
    missing = [n for n in names if n not in known]
    if missing:
        raise RuntimeError('not in the scene: ' + ', '.join(missing))
    return known


def center(name):
    return np.array(get_object_center_position(name), dtype=float)


def bbox(name):
    return np.array(get_3d_bbox(name), dtype=float)


def half_extents(name):
    # Half sizes along x and y and the full height of the object's world-aligned box.
    b = bbox(name)
    return (b[3] - b[0]) / 2.0, (b[4] - b[1]) / 2.0, b[5] - b[2]


def xy_distance(p, q):
    return float(np.hypot(p[0] - q[0], p[1] - q[1]))


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    v = np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])
    return v / np.linalg.norm(v)


def retreat_hand():
    # Open the fingers and pull the hand back out the way it came, then up; failures here are not fatal.
    open_gripper()
    for axis, distance in ((-approach_axis(get_gripper_pose()), 0.08), (UP, 0.05)):
        try:
            move_in_direction(axis, distance)
        except ROBOT_ERRORS:
            pass


def grasp_options(name):
    # Ordered grasp generators: the first is tried, the second is the retry with another grasp tool.
    def central():
        return parse_central_lift_grasp_pose(object_name=name, description='center')

    def adaptive():
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])

    def horizontal():
        return parse_horizontal_grasp_pose(object_name=name)

    if 'cup' in name or 'mug' in name:
        return [('adaptive', adaptive), ('horizontal', horizontal)]
    return [('central lift', central), ('adaptive', adaptive)]


def pick(name, lift=0.1):
    # Grasp, close, attach (attach_object raises GraspError when nothing is held), lift; retry once with another tool.
    if is_fixed(name):
        raise RuntimeError('%s cannot be picked up' % name)
    errors = []
    for label, make_pose in grasp_options(name):
        open_gripper()
        try:
            pose = make_pose()
        except ROBOT_ERRORS as e:
            errors.append('%s grasp: %s' % (label, e))
            continue
        try:
            grasp(pose)
            close_gripper()
            attach_object(name)
        except ROBOT_ERRORS as e:
            errors.append('%s grasp: %s' % (label, e))
            retreat_hand()
            detect_objects([name])  # it may have been nudged
            continue
        try:
            move_in_direction(UP, lift)
        except ROBOT_ERRORS:
            move_in_direction(UP, 0.05)
        return label
    raise RuntimeError('could not pick up %s (%s)' % (name, '; '.join(errors)))


def place(name, receptacle=None, position=None):
    # Set the held object down (in/on a receptacle, or at a position), release, move away, re-detect the scene.
    if receptacle is None and position is None:
        raise RuntimeError('place() needs a receptacle or a position')
    last_error = None
    for attempt in range(2):
        try:
            if receptacle is not None and position is not None:
                pose = parse_place_pose(object_name=name, receptacle_name=receptacle,
                                        position=[float(v) for v in position])
            elif receptacle is not None:
                pose = parse_place_pose(object_name=name, receptacle_name=receptacle)
            else:
                pose = parse_place_pose(object_name=name, position=[float(v) for v in position])
            move_to_pose(pose)
        except ReceptacleFullError as e:
            raise RuntimeError('%s is full, %s cannot go in: %s' % (receptacle, name, e))
        except ROBOT_ERRORS as e:
            last_error = e
            try:
                move_in_direction(UP, 0.05)  # a little more clearance before the second try
            except ROBOT_ERRORS:
                pass
            continue
        open_gripper()
        detach_object(name)
        try:
            move_in_direction(UP, 0.1)
        except ROBOT_ERRORS:
            move_in_direction(-approach_axis(get_gripper_pose()), 0.08)
        detect_objects()
        return center(name)
    raise RuntimeError('could not set %s down (%s)' % (name, last_error))


def square_around(point, half):
    # An xy footprint (as a bbox) of half size `half` around `point`.
    return np.array([point[0] - half, point[1] - half, -10.0, point[0] + half, point[1] + half, 10.0])


def boxes_overlap_xy(a, b, margin=0.0):
    return (a[0] - margin < b[3] and b[0] - margin < a[3] and
            a[1] - margin < b[4] and b[1] - margin < a[4])


def obstacle_boxes(ignore=()):
    # Every thing that takes room on the table: objects and the cabinet body (its parts lie inside it).
    boxes = []
    for n in get_object_name_list():
        if n == 'table' or n.startswith('cabinet.') or n in ignore:
            continue
        boxes.append(bbox(n))
    return boxes


def spot_ok(x, y, hx, hy, boxes, margin=0.03, r_min=0.3, r_max=0.75, edge=0.03):
    # On the table top (with an edge margin), reachable (not too near or far from the base) and clear of boxes.
    t = bbox('table')
    if x - hx < t[0] + edge or x + hx > t[3] - edge or y - hy < t[1] + edge or y + hy > t[4] - edge:
        return False
    r = np.hypot(x, y)
    if r < r_min or r > r_max:
        return False
    footprint = np.array([x - hx, y - hy, 0.0, x + hx, y + hy, 0.0])
    return not any(boxes_overlap_xy(footprint, b, margin) for b in boxes)


def find_free_spot(name, near, keep_free=(), ignore=(), margin=0.03, step=0.02):
    # Grid search over the table for the free, reachable spot nearest `near` where `name` fits (any turn of it).
    hx, hy, height = half_extents(name)
    half = max(hx, hy)
    t = bbox('table')
    boxes = obstacle_boxes(ignore=[name] + list(ignore)) + list(keep_free)
    best, best_d = None, None
    for x in np.arange(t[0] + half, t[3] - half + 1e-9, step):
        for y in np.arange(t[1] + half, t[4] - half + 1e-9, step):
            if not spot_ok(x, y, half, half, boxes, margin):
                continue
            d = np.hypot(x - near[0], y - near[1])
            if best is None or d < best_d:
                best, best_d = (x, y), d
    if best is None:
        raise RuntimeError('no free spot on the table for %s' % name)
    return np.array([best[0], best[1], t[5] + height / 2.0])


def xy_gap(a, b):
    # Horizontal clearance between two world-aligned boxes (negative when their footprints overlap).
    return max(a[0] - b[3], b[0] - a[3], a[1] - b[4], b[1] - a[4])


def spot_beside(mover, anchor, gap=0.03):
    # Candidate spots touching the anchor's box on each side (left +y, right -y, front -x, back +x), stepping
    # a little further out when a ring is taken; the mover keeps its turn, so its own half sizes are used.
    a = bbox(anchor)
    ac = center(anchor)
    mc = center(mover)
    hx, hy, height = half_extents(mover)
    boxes = obstacle_boxes(ignore=[mover, anchor])
    table_top = bbox('table')[5]
    for extra in (0.0, 0.03, 0.06):
        g = gap + extra
        candidates = [
            (ac[0], a[4] + g + hy),   # left
            (ac[0], a[1] - g - hy),   # right
            (a[0] - g - hx, ac[1]),   # front (towards the robot)
            (a[3] + g + hx, ac[1]),   # back
        ]
        free = [(x, y) for x, y in candidates if spot_ok(x, y, hx, hy, boxes, margin=0.02)]
        if free:
            x, y = min(free, key=lambda p: np.hypot(p[0] - mc[0], p[1] - mc[1]))
            return np.array([x, y, table_top + height / 2.0])
    raise RuntimeError('no free spot beside %s for %s' % (anchor, mover))


# ---------- main ----------
detect_objects()
require_names([MOVER, ANCHOR])
if 0.0 <= xy_gap(bbox(MOVER), bbox(ANCHOR)) <= 0.05:
    print('%s already stands beside %s' % (MOVER, ANCHOR))
else:
    target = spot_beside(MOVER, ANCHOR)
    pick(MOVER)
    place(MOVER, position=target)
    gap = xy_gap(bbox(MOVER), bbox(ANCHOR))
    if gap < -0.005 or gap > 0.10:
        raise RuntimeError('%s ended %.3f m from %s, not beside it' % (MOVER, gap, ANCHOR))
