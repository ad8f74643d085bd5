# Task: put the wooden bar into the cabinet behind its door; the door is closed, open it first.
# Plan:
# 1. The cabinet's rows from the top are cabinet.door_0, then cabinet.drawer_0, so the door's
#    handle is cabinet.handle_0. Look at the scene, check the names exist, and check against the
#    geometry that handle_0 is the handle nearest to the door.
# 2. Read the door's revolute joint (it should be shut) and, while it is shut, remember the
#    cabinet's box, the door's box, the handle's position and the front's outward normal: they
#    describe the compartment behind the door.
# 3. Open the door wide (90 degrees, or 2 short of its limit): in rounds, grasp the handle
#    (horizontal; else horizontal moving towards the front; else adaptive), check the hand got
#    there, close, attach the door (GraspError: nothing held), follow an arc about the hinge by the
#    angle still missing, open, detach, back away; look again and read the joint. Up to three
#    rounds. Placing into the compartment needs 40 degrees: go on only from 45 (5 degrees for the
#    reading).
# 4. Pick the wooden bar with a horizontal grasp (required to carry it in level): default approach,
#    else moving towards the cabinet, else moving forward; each checked (hand at the grasp pose,
#    attach raises on empty fingers, a new look shows the bar rose with the hand).
# 5. Ask for a place pose into the compartment (receptacle cabinet.door_0), move there (if the arm
#    cannot, rise 3 cm and ask again once), check the hand got there, open, detach, and back out
#    along the front's outward normal.
# 6. Look again: the bar's centre must be within the cabinet's box, between the door's bottom and
#    top, and behind the front; else give up with a RuntimeError.

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


def pick(name, options, lift=0.10):
    failures = []
    for label, make_grasp in options:
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


detect_objects()
require_names('wooden_bar', 'cabinet', DOOR, HANDLE)
check_handle(DOOR, HANDLE)

# 2. The compartment, measured while the door is shut.
handle_at, joint = read_joint(DOOR, HANDLE, 'revolute')
door_was_shut = float(joint['joint_value']) < 5.0  # 5 degrees: reading noise, a door left ajar
if not door_was_shut:
    print('the door is already open %.0f degrees; the compartment checks are looser'
          % float(joint['joint_value']))
cabinet_box = get_3d_bbox('cabinet')
door_box = get_3d_bbox(DOOR)
front_point = np.array(handle_at, dtype=float)
front_normal = np.array(get_plane_normal(DOOR if door_was_shut else 'cabinet', handle_at), dtype=float)

# 3. Open the door wide.
aim = min(90.0, float(joint['joint_upper']) - 2.0)
if aim < 45.0:
    raise RuntimeError('the door opens only %.0f degrees; the compartment needs 40 or more'
                       % float(joint['joint_upper']))
opened = open_door_to(DOOR, HANDLE, aim, 5.0)
if opened < 45.0:
    raise RuntimeError('the cabinet door opened only %.0f degrees; the compartment needs 40 or more' % opened)

# 4. Pick the bar with a horizontal grasp, so that it can be carried in level.
inward = list(-front_normal)
bar_options = [
    ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name='wooden_bar')),
    ('horizontal grasp moving towards the cabinet',
     lambda: parse_horizontal_grasp_pose(object_name='wooden_bar', approach_direction=inward)),
    ('horizontal grasp moving forward',
     lambda: parse_horizontal_grasp_pose(object_name='wooden_bar', approach_direction=[1, 0, 0])),
]
pick('wooden_bar', bar_options)

# 5. Into the compartment, then back out the way in.
failures = []
for attempt in range(2):
    try:
        place_pose = parse_place_pose(object_name='wooden_bar', receptacle_name=DOOR)
        move_to_pose(place_pose)
    except (PlanningError, IKError) as error:
        failures.append(str(error))
        try_move([0, 0, 1], 0.03)
        continue
    except (PlacementError, ReceptacleFullError, CompartmentError) as error:
        raise RuntimeError('no place for the wooden bar behind the door: %s' % error)
    if not tcp_reached(place_pose):
        raise RuntimeError('the hand did not reach the place pose in the compartment')
    open_gripper()
    detach_object('wooden_bar')
    if not try_move(front_normal, 0.20) and not try_move(front_normal, 0.10):
        back_off()
    break
else:
    raise RuntimeError('could not carry the wooden bar into the compartment (%s)' % '; '.join(failures))

# 6. Check: inside the cabinet's box (measured with the door shut), at the compartment's height
#    (the door's bottom to top, 2 cm for detection noise) and behind the front (behind the handle,
#    which stands out of it).
detect_objects()
bar = get_object_center_position('wooden_bar')
in_cabinet = inside_xy(bar, cabinet_box)
at_height = door_box[2] - 0.02 <= bar[2] <= door_box[5] + 0.02
behind_front = float(np.dot(bar - front_point, front_normal)) < 0.0
if not (in_cabinet and at_height and behind_front):
    raise RuntimeError('the wooden bar is not in the compartment behind the door (in the cabinet: %s, '
                       'at its height: %s, behind the front: %s)' % (in_cabinet, at_height, behind_front))
