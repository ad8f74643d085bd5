# Task: open the second drawer of the cabinet and put the yellow box into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1; its handle is on row 1: cabinet.handle_1.
#    Look at the scene, check the names exist, and check against the geometry that handle_1 is the
#    handle nearest to drawer_1's box (not another drawer's).
# 2. Read drawer_1's prismatic joint near the handle: how far it is open and how far it can open.
#    Aim for 1 cm short of its limit (as much room as possible without pulling against the stop).
# 3. Open it: grasp the handle (horizontal grasp; else horizontal moving towards the cabinet; else
#    adaptive), check the hand got there, close, attach the drawer (GraspError: nothing held), pull
#    along +axis by the difference (70 % of it if the arm cannot reach), open, detach, back away
#    along +axis.
# 4. Look again and read the joint: it must be within 3 cm of the aim; if not, a second round from
#    the new state. If still short, go on only if the opening exceeds the box's narrower side + 2 cm.
# 5. Pick the yellow box (up to three grasp tools, each checked: attach, and a new look shows it rose
#    with the hand), place it into cabinet.drawer_1, check the hand reached the place pose, release,
#    move up.
# 6. Look again: the box's centre must be over the drawer's footprint and its bottom between the
#    drawer's bottom and top. If not, pick and place once more; then give up with a RuntimeError.

MOTION_ERRORS = (GraspError, PlanningError, IKError, FailureError)
DRAWER = 'cabinet.drawer_1'
HANDLE = 'cabinet.handle_1'


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


def box_in_drawer():
    # In the drawer: the box's centre over the drawer's footprint, its bottom not below the
    # drawer's bottom (1 cm allowed for detection noise) and below the drawer's top edge (resting
    # inside, not on the cabinet or on the drawer's front).
    detect_objects()
    center = get_object_center_position('yellow_box')
    bottom = get_3d_bbox('yellow_box')[2]
    drawer = get_3d_bbox(DRAWER)
    return inside_xy(center, drawer) and drawer[2] - 0.01 <= bottom <= drawer[5]


detect_objects()
require_names('yellow_box', 'cabinet', DRAWER, HANDLE)
check_handle(DRAWER, HANDLE)

# The box needs at least its narrower side, plus 2 cm of play, of open drawer to go in from above.
box_bb = get_3d_bbox('yellow_box')
needed = min(box_bb[3] - box_bb[0], box_bb[4] - box_bb[1]) + 0.02

handle_at, joint = read_joint(DRAWER, HANDLE, 'prismatic')
aim = float(joint['joint_upper']) - 0.01
opening = set_drawer(DRAWER, HANDLE, aim, 0.03)  # 3 cm: handle slip and measurement noise
if opening < aim - 0.03:
    if opening < needed:
        raise RuntimeError('the second drawer is open only %.3f m; the yellow box needs %.3f m'
                           % (opening, needed))
    print('the second drawer is open %.3f m of %.3f m, enough for the yellow box' % (opening, aim))

for attempt in range(2):
    pick('yellow_box')
    place('yellow_box', receptacle=DRAWER)
    if box_in_drawer():
        break
else:
    raise RuntimeError('the yellow box is not in the second drawer after two tries')
