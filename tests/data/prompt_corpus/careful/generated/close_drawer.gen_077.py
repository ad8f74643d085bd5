# Task: close the open drawer
# Plan:
# 1. Rows from the top: cabinet.drawer_0 (handle_0), cabinet.drawer_1 (handle_1), cabinet.door_0 (handle_2).
# 2. Detect, and read each drawer's prismatic joint near its handle: the open drawer is the one whose
#    joint_value (metres out) is clearly above 0 (the most open one, should more be out). None open: done.
# 3. Grasp its handle level, close the gripper, attach the drawer, push it along -axis by exactly as far as it
#    is out, release it and back away along +axis.
# 4. Look again: its joint_value must be about 0; if not, grip the handle again and push the rest.
# 5. Check the other drawer, the door and the things on the table have not moved.
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


DRAWERS = {'cabinet.drawer_0': 'cabinet.handle_0', 'cabinet.drawer_1': 'cabinet.handle_1'}
DOOR, DOOR_HANDLE = 'cabinet.door_0', 'cabinet.handle_2'
SHUT = 0.01  # metres: out by less than this counts as closed


def main():
    detect_objects()
    things_before = positions(things_on_table())
    out = {d: float(joint_at(h, 'prismatic')['joint_value']) for d, h in DRAWERS.items()}
    open_ones = [d for d in DRAWERS if out[d] > SHUT]
    if not open_ones:
        print('no drawer is open: nothing to close')
        return
    drawer = max(open_ones, key=lambda d: out[d])
    handle = DRAWERS[drawer]
    untouched = {d: (h, 'prismatic') for d, h in DRAWERS.items() if d != drawer}
    untouched[DOOR] = (DOOR_HANDLE, 'revolute')
    untouched_before = joint_snapshot(untouched)

    value = move_drawer(drawer, handle, 0.0, lambda v: v <= SHUT)
    if value > SHUT:
        raise RuntimeError('%s is still %.3f m out after two pushes' % (drawer, value))

    report_joints_changed(untouched_before)
    report_moved(things_before)


main()
