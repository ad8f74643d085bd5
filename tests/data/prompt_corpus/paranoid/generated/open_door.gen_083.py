# Task: open the cabinet door wide.
# Plan:
# 1. The cabinet's rows from the top are cabinet.door_0, then cabinet.drawer_0, so the door's
#    handle is cabinet.handle_0 (the drawer's is cabinet.handle_1). Look at the scene, check the
#    names exist, and check against the geometry that handle_0 is the handle nearest to the door.
# 2. Read the door's revolute joint near its handle: how far it is open and how far it can open.
#    "Wide": 90 degrees, or 2 degrees short of the limit where that is less.
# 3. Open it in rounds: grasp the handle (horizontal grasp; else horizontal moving towards the door
#    front; else adaptive), check the hand got there, close, attach the door (GraspError: nothing
#    held), follow an arc about the hinge by the angle still missing (about 3 degrees per pose),
#    open, detach, back away along the hand's approach axis; look again and read the joint.
#    A round may stop short where the arm runs out of reach: then grasp the handle again where it
#    now is and go on, up to three rounds, until within 5 degrees of the aim.
# 4. The door must end within 10 degrees of the aim, else give up with a RuntimeError.

MOTION_ERRORS = (GraspError, PlanningError, IKError, FailureError)
DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'


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
    # inward: the way the hand moves in, towards the front the handle is on.
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


def open_door_to(part, handle, target, tolerance, tries=3):
    # Each round: grasp the handle where it is now, swing the door about its hinge by the angle
    # still missing, let go, back away, and read the joint again. Returns the last reading (deg).
    for attempt in range(tries):
        handle_at, joint = read_joint(part, handle, 'revolute')
        missing = target - float(joint['joint_value'])
        if missing <= tolerance:
            return float(joint['joint_value'])
        outward = np.array(get_plane_normal(part, handle_at), dtype=float)  # out of the door front
        grab_handle(part, handle, -outward)
        steps = int(max(10, np.ceil(missing / 3.0)))  # about 3 degrees between poses
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                              joint_position=joint['joint_position'], n=steps, angle=missing)
        try:
            follow_path(path)
        except MOTION_ERRORS as error:
            print('round %d: swinging %s stopped: %s' % (attempt + 1, part, error))
        open_gripper()
        detach_object(part)
        back_off()
    handle_at, joint = read_joint(part, handle, 'revolute')
    return float(joint['joint_value'])


detect_objects()
require_names('cabinet', DOOR, HANDLE)
check_handle(DOOR, HANDLE)

handle_at, joint = read_joint(DOOR, HANDLE, 'revolute')
aim = min(90.0, float(joint['joint_upper']) - 2.0)
# 5 degrees: close enough to stop trying (readings are good to a degree or two).
opened = open_door_to(DOOR, HANDLE, aim, 5.0)
# 10 degrees: a door within 10 degrees of 90 (or of its limit) is wide open.
if opened < aim - 10.0:
    raise RuntimeError('the cabinet door is open only %.0f degrees of the %.0f aimed for' % (opened, aim))
