# Task: swap the positions of the red box and the baseball
# Plan:
# 1. Detect everything; remember where the red box and the baseball stand before anything moves, and where
#    the other things are (they stay put).
# 2. Set the red box aside on a free spot of the table (at least 15 cm from its place, which stays free).
# 3. Move the baseball to where the red box stood; look again (a ball may roll): it must be within 6 cm of that
#    spot, else pick it up again and place it once more.
# 4. Move the red box to where the baseball stood; look again and check the same way.
# 5. Grasps: both from above across their narrower side (the adaptive grasp if that does not fit or the fingers
#    close on nothing). Finally check both and that nothing else has moved.
ROBOT_ERRORS = (FailureError, GraspError, PlacementError, ReceptacleFullError, CompartmentError, PlanningError, IKError)
FIXTURE_WORDS = ('plate', 'saucer', 'bowl', 'basket')  # these stay where they are


def vec(values):
    # A plain list of floats for the tools' vector arguments.
    return [float(v) for v in values]


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def move_if_possible(axis, distance):
    # A lift or retreat whose failure does no harm.
    try:
        move_in_direction(vec(axis), distance)
    except ROBOT_ERRORS:
        pass


def back_off(distance):
    # Straight back along the hand's approach axis.
    move_if_possible(-approach_axis(get_gripper_pose()), distance)


def things_on_table():
    # Every name but the table and the furniture with its parts.
    return [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet')]


def xy_inside(point, box, margin):
    # Whether point's x, y lie within the box's x, y extent (widened by margin).
    return bool(box[0] - margin <= point[0] <= box[3] + margin and box[1] - margin <= point[1] <= box[4] + margin)


def positions(names):
    # Copies of the present centres (call detect_objects() first).
    return {n: np.array(get_object_center_position(n), dtype=float) for n in names}


def report_moved(before, tolerance=0.03):
    # Look again and name anything the task did not mention that has moved.
    detect_objects()
    moved = []
    for n, p in before.items():
        now = get_object_center_position(n)
        if np.hypot(now[0] - p[0], now[1] - p[1]) > tolerance:
            moved.append(n)
    if moved:
        print('[warning] moved though the task did not ask for it: ' + ', '.join(moved))
    return moved


def default_grasps(name):
    # The grasp follows the shape: mugs and cups by rim or handle (adaptive grasp, from above); compact things
    # (blocks, cubes, boxes, balls, bottles, cans, fruit) from above across their narrower side. The other kind
    # follows if the first does not fit (wider than the opening) or closes on nothing.
    top = ('from above', lambda: parse_central_lift_grasp_pose(object_name=name, description='center'))
    adaptive = ('adaptive', lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    if 'mug' in name or 'cup' in name:
        return [adaptive, top]
    return [top, adaptive]


def pick(name, grasps):
    # Try the grasp kinds in order; one that does not fit, cannot be reached or closes on nothing is followed
    # by the next. Once held, lift 10 cm more (attach_object already lifts 5 cm).
    problems = []
    for label, make_pose in grasps:
        detect_objects(object_list=[name])
        try:
            pose = make_pose()
        except ROBOT_ERRORS as error:
            problems.append('%s: %s' % (label, error))
            continue
        open_gripper()
        try:
            grasp(pose)
            close_gripper()
            attach_object(name)
        except ROBOT_ERRORS as error:
            problems.append('%s: %s' % (label, error))
            open_gripper()
            back_off(0.1)
            continue
        move_if_possible([0, 0, 1], 0.1)
        return
    raise RuntimeError('could not pick up %s (%s)' % (name, '; '.join(problems)))


def release(name, retreat_up=True):
    # Let go, tell the planner, move away (up, or back out the way the hand came).
    open_gripper()
    detach_object(name)
    if retreat_up:
        move_if_possible([0, 0, 1], 0.1)
    else:
        back_off(0.1)


def set_down(name, options, retreat_up=True):
    # options: (receptacle, position) pairs tried in order; True once the held object is let go.
    for receptacle, position in options:
        spot = None if position is None else vec(position)
        try:
            move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=spot))
        except ROBOT_ERRORS:
            continue
        release(name, retreat_up)
        return True
    return False


def set_back(name, home):
    # It cannot go where asked: put it back where it was (or aside on the table) rather than hold it.
    if not set_down(name, [(None, home), ('table', None)]):
        raise RuntimeError('%s is still held: it can be set down neither as asked nor back where it was' % name)


def transfer(name, options, holds, grasps=None, retreat_up=True):
    # Pick `name` up and set it down by the first workable (receptacle, position) option; holds(), after a
    # fresh look, says whether the result is right. If not, once more another way: pick it up again with the
    # next grasp kind first and the next option first.
    for attempt in range(2):
        detect_objects()
        home = np.array(get_object_center_position(name), dtype=float)
        kinds = grasps if grasps is not None else default_grasps(name)
        g = attempt % len(kinds)
        pick(name, kinds[g:] + kinds[:g])
        o = attempt % len(options)
        if not set_down(name, options[o:] + options[:o], retreat_up):
            set_back(name, home)
            raise RuntimeError('could not set %s down as asked: no reachable free place' % name)
        detect_objects()
        if holds():
            return
    raise RuntimeError('%s is not where it was asked to go, even after a second try' % name)


BOX, BALL = 'red_box', 'baseball'
TOLERANCE = 0.06  # metres: how close to the other's old spot counts as there


def near(name, spot, tolerance):
    centre = get_object_center_position(name)
    return bool(np.hypot(centre[0] - spot[0], centre[1] - spot[1]) <= tolerance)


detect_objects()
things_before = positions([n for n in things_on_table() if n not in (BOX, BALL)])
box_at = np.array(get_object_center_position(BOX), dtype=float)
ball_at = np.array(get_object_center_position(BALL), dtype=float)

transfer(BOX, [('table', None)], lambda: not near(BOX, box_at, 0.10))
transfer(BALL, [(None, box_at), ('table', box_at)], lambda: near(BALL, box_at, TOLERANCE))
transfer(BOX, [(None, ball_at), ('table', ball_at)], lambda: near(BOX, ball_at, TOLERANCE))

detect_objects()
if not (near(BALL, box_at, TOLERANCE) and near(BOX, ball_at, TOLERANCE)):
    raise RuntimeError('the red box and the baseball did not end up in each other\'s places')
report_moved(things_before)
