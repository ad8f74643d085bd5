# Task: put the red block into the footed bowl.
# Plan:
# 1. Detect everything and check red_block and footed_bowl exist; if the block is already in the bowl
#    (centre over the bowl's bounding box, bottom between the bowl's bottom and rim), nothing is to be done.
# 2. Pick the block: top-down central grasp, retry once with the adaptive grasp if that fails; lift it
#    higher than the bowl's rim (the footed bowl stands tall) plus 5 cm.
# 3. Get a place pose into the bowl, move there, release, move up (one retry of the place if planning fails).
# 4. Re-detect the block and the bowl and verify the block is inside; otherwise raise RuntimeError.
ITEM = 'red_block'
RECEPTACLE = 'footed_bowl'

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


def rests_in(name, receptacle, margin=0.01):
    # The object's centre is over the receptacle's footprint and its bottom between the receptacle's bottom
    # and (just above) its top: inside a bowl, basket or drawer, or lying on a plate.
    c = center(name)
    o = bbox(name)
    r = bbox(receptacle)
    over = r[0] - margin <= c[0] <= r[3] + margin and r[1] - margin <= c[1] <= r[4] + margin
    return over and r[2] - 0.01 <= o[2] <= r[5] + 0.02


def clearance_lift(name, receptacle):
    # Lift high enough to carry the object's bottom over the receptacle's rim.
    return float(min(0.3, max(0.1, bbox(receptacle)[5] - bbox(name)[2] + 0.05)))


def put_into(name, receptacle):
    if rests_in(name, receptacle):
        print('%s is already in/on %s' % (name, receptacle))
        return
    pick(name, lift=clearance_lift(name, receptacle))
    place(name, receptacle=receptacle)
    detect_objects([name, receptacle])
    if not rests_in(name, receptacle):
        raise RuntimeError('%s did not end up in/on %s' % (name, receptacle))


# ---------- main ----------
detect_objects()
require_names([ITEM, RECEPTACLE])
put_into(ITEM, RECEPTACLE)
