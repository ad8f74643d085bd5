# Task: open the cabinet door and put the peach in the cupboard behind it
# Plan:
# 1. The door is listed first, so it is the top row: cabinet.door_0 with cabinet.handle_0; the drawer below
#    it is cabinet.drawer_0 with cabinet.handle_1 (it stays closed).
# 2. Detect; note the closed cabinet's box (the compartment lies inside it) and the door front's inward
#    direction; read the door's revolute joint (degrees).
# 3. Open the door: grasp its handle level, attach the door, follow an arc about the hinge towards 90 degrees
#    (or its limit), release, back off. Look again; if short, grip it anew and turn the rest. Placing into
#    the compartment needs at least 40 degrees.
# 4. Pick the peach with a level (horizontal) grasp, as carrying it into the compartment asks, preferably
#    with the hand moving in the way it will go into the cupboard; lift it.
# 5. Place it into the compartment behind the door, release it, back the hand out the way it came.
# 6. Look again: the peach must lie inside the cabinet's box; if not, pick it up again (the other level grasp)
#    and place it once more. Check the drawer and the other things have not moved.
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


def joint_at(handle, kind):
    # The cabinet's joint of this kind nearest the handle (call detect_objects() first).
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type=kind)


def grab_handle(part, handle):
    # Grasp the handle level against its front, close, attach the drawer or door. If that does not fit or the
    # fingers close on nothing, once more with the adaptive grasp moving in against the front.
    problems = []
    for label in ('level', 'adaptive'):
        detect_objects()
        handle_at = get_object_center_position(handle)
        try:
            if label == 'level':
                pose = parse_horizontal_grasp_pose(object_name=handle)
            else:
                inward = -np.array(get_plane_normal(part, handle_at), dtype=float)
                pose = parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=vec(handle_at), preferred_approach_direction=vec(inward))
        except ROBOT_ERRORS as error:
            problems.append('%s grasp: %s' % (label, error))
            continue
        open_gripper()
        try:
            grasp(pose)
            close_gripper()
            attach_object(part)
            return
        except ROBOT_ERRORS as error:
            problems.append('%s grasp: %s' % (label, error))
            open_gripper()
            back_off(0.08)
    raise RuntimeError('could not take hold of %s (%s)' % (handle, '; '.join(problems)))


def move_drawer(part, handle, target, good):
    # Slide the drawer along its joint to `target` metres out (+axis pulls open, -axis pushes shut), let go and
    # back away along +axis; look again, and grip it once more for what is left if good(value) is not met.
    for attempt in range(2):
        detect_objects()
        joint = joint_at(handle, 'prismatic')
        value = float(joint['joint_value'])
        if good(value):
            return value
        axis = vec(joint['joint_axis'])
        grab_handle(part, handle)
        try:
            move_in_direction(axis, float(target) - value)
        except ROBOT_ERRORS:
            pass  # measured below
        open_gripper()
        detach_object(part)
        move_if_possible(axis, 0.05)
    detect_objects()
    return float(joint_at(handle, 'prismatic')['joint_value'])


def turn_door(part, handle, target, good):
    # Swing the door about its hinge to `target` degrees (a positive angle opens it), let go and back off; look
    # again, and if the arm fell short grip the handle anew where it is now and turn the rest.
    for attempt in range(2):
        detect_objects()
        joint = joint_at(handle, 'revolute')
        value = float(joint['joint_value'])
        if good(value):
            return value
        angle = float(target) - value
        grab_handle(part, handle)
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=max(10, int(abs(angle) / 3)), angle=angle)
        try:
            follow_path(path)
        except ROBOT_ERRORS:
            pass  # measured below
        open_gripper()
        detach_object(part)
        back_off(0.08)
    detect_objects()
    return float(joint_at(handle, 'revolute')['joint_value'])


def joint_snapshot(parts):
    # parts: {part: (handle, kind)} -> {part: (handle, kind, value now)} (call detect_objects() first).
    return {p: (h, k, float(joint_at(h, k)['joint_value'])) for p, (h, k) in parts.items()}


def report_joints_changed(before):
    # Look again and name any drawer or door the task did not mention that has moved.
    detect_objects()
    changed = []
    for part, (handle, kind, value) in before.items():
        now = float(joint_at(handle, kind)['joint_value'])
        if abs(now - value) > (0.01 if kind == 'prismatic' else 3.0):
            changed.append('%s (%.3f -> %.3f)' % (part, value, now))
    if changed:
        print('[warning] moved though the task did not ask for it: ' + ', '.join(changed))
    return changed


DOOR, DOOR_HANDLE = 'cabinet.door_0', 'cabinet.handle_0'
DRAWER, DRAWER_HANDLE = 'cabinet.drawer_0', 'cabinet.handle_1'
PEACH = 'peach'
NEEDED = 40.0  # degrees open before anything can be placed behind the door

detect_objects()
things_before = positions([n for n in things_on_table() if n != PEACH])
drawer_before = joint_snapshot({DRAWER: (DRAWER_HANDLE, 'prismatic')})
cabinet_box = np.array(get_3d_bbox('cabinet'), dtype=float)  # taken while the door is shut
inward = -np.array(get_plane_normal(DOOR, get_object_center_position(DOOR_HANDLE)), dtype=float)
inward[2] = 0.0
if np.linalg.norm(inward) < 1e-6:
    inward = np.array([1.0, 0.0, 0.0])
inward = inward / np.linalg.norm(inward)

upper = float(joint_at(DOOR_HANDLE, 'revolute')['joint_upper'])
if upper < NEEDED:
    raise RuntimeError('the door opens only %.0f degrees; %.0f are needed to put something behind it' % (upper, NEEDED))
target = min(upper - 1.0, 90.0)
value = turn_door(DOOR, DOOR_HANDLE, target, lambda v: v >= max(NEEDED, 0.8 * target))
if value < NEEDED:
    raise RuntimeError('the door opened only %.0f degrees; %.0f are needed' % (value, NEEDED))


def in_cupboard():
    centre = get_object_center_position(PEACH)
    return xy_inside(centre, cabinet_box, 0.0) and bool(cabinet_box[2] <= centre[2] <= cabinet_box[5])


level_grasps = [
    ('level, moving in as into the cupboard', lambda: parse_horizontal_grasp_pose(object_name=PEACH, approach_direction=vec(inward))),
    ('level', lambda: parse_horizontal_grasp_pose(object_name=PEACH)),
]
transfer(PEACH, [(DOOR, None)], in_cupboard, grasps=level_grasps, retreat_up=False)

report_joints_changed(drawer_before)
report_moved(things_before)
