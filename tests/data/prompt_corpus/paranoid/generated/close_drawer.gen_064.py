# Task: close the second drawer of the cabinet.
# Plan:
# 1. The cabinet's rows from the top are cabinet.drawer_0, cabinet.drawer_1, cabinet.door_0, so the
#    second drawer is cabinet.drawer_1 and its handle cabinet.handle_1. Look at the scene, check the
#    names exist, and check against the geometry that handle_1 is the handle nearest to drawer_1.
# 2. Read drawer_1's prismatic joint near the handle. If it is already shut (within 1 cm), stop.
# 3. Close it: grasp the handle (horizontal grasp; else horizontal moving towards the cabinet; else
#    adaptive), check the hand got there, close the gripper, attach the drawer (GraspError: nothing
#    held), push along -axis by as far as it is open (70 % of it if the arm cannot), open, detach,
#    back away along +axis.
# 4. Look again and read the joint: it must be within 1 cm of shut; if not, a second round from the
#    new state. Still open after that: give up with a RuntimeError.

MOTION_ERRORS = (GraspError, PlanningError, IKError, FailureError)
DRAWER = 'cabinet.drawer_1'
HANDLE = 'cabinet.handle_1'
SHUT = 0.01  # 1 cm: a drawer out by less is shut for any use; a push that stalls leaves more


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


def check_handle(part, handle):
    # The numbering rule names the part's handle; check it against the geometry: of all handles,
    # the part's own sits on its front, so it is the nearest to the part's box.
    handles = [name for name in get_object_name_list() if name.startswith('cabinet.handle_')]
    box = get_3d_bbox(part)

    def gap(name):
        point = get_object_center_position(name)
        return float(np.linalg.norm(np.maximum(np.maximum(box[:3] - point, point - box[3:]), 0.0)))

    nearest = min(handles, key=gap)
    if nearest != handle:
        raise RuntimeError('%s, not %s, is the handle nearest to %s: the numbering does not match'
                           % (nearest, handle, part))


def read_joint(part, handle, kind):
    detect_objects()  # the part may have moved: measure anew
    handle_at = get_object_center_position(handle)
    joint = get_object_joint_info(object_name=part, position=handle_at, type=kind)
    if kind not in str(joint['type']).lower():
        raise RuntimeError('expected a %s joint at %s, found %s' % (kind, handle, joint['type']))
    return handle_at, joint


def grab_handle(part, handle, inward):
    # inward: the way the hand moves in, towards the cabinet front.
    handle_at = get_object_center_position(handle)
    options = [
        ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name=handle)),
        ('horizontal grasp moving towards the front',
         lambda: parse_horizontal_grasp_pose(object_name=handle, approach_direction=list(inward))),
        ('adaptive grasp', lambda: parse_adaptive_shape_grasp_pose(
            object_name=handle, preferred_position=list(handle_at), preferred_approach_direction=list(inward))),
    ]
    failures = []
    for label, make_grasp in options:
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
            failures.append('%s: the hand stopped short of the handle' % label)
            back_off()
            continue
        close_gripper()
        try:
            attach_object(part)  # GraspError where the fingers closed on nothing
        except MOTION_ERRORS as error:
            failures.append('%s: %s' % (label, error))
            open_gripper()
            back_off()
            continue
        return
    raise RuntimeError('could not take hold of %s (%s)' % (handle, '; '.join(failures)))


def set_drawer(part, handle, target, tolerance, tries=2):
    # Each round: read the opening, grasp the handle, move the hand along the drawer's axis by the
    # difference (+ pulls out, - pushes in; 70 % of it if the arm cannot go that far), let go,
    # back away, and read again. Returns the last reading (metres).
    for attempt in range(tries):
        handle_at, joint = read_joint(part, handle, 'prismatic')
        delta = target - float(joint['joint_value'])
        if abs(delta) <= tolerance:
            return float(joint['joint_value'])
        axis = np.array(joint['joint_axis'], dtype=float)
        grab_handle(part, handle, -axis)
        if not try_move(axis, delta) and not try_move(axis, 0.7 * delta):
            print('could not move %s along its axis in round %d' % (part, attempt + 1))
        open_gripper()
        detach_object(part)
        if not try_move(axis, 0.05):
            back_off()
    handle_at, joint = read_joint(part, handle, 'prismatic')
    return float(joint['joint_value'])


detect_objects()
require_names('cabinet', DRAWER, HANDLE)
check_handle(DRAWER, HANDLE)

handle_at, joint = read_joint(DRAWER, HANDLE, 'prismatic')
if float(joint['joint_value']) <= SHUT:
    print('the second drawer is already closed (%.3f m out)' % float(joint['joint_value']))
else:
    left_open = set_drawer(DRAWER, HANDLE, 0.0, SHUT)
    if left_open > SHUT:
        raise RuntimeError('the second drawer is still %.3f m open after two rounds' % left_open)
