# Task: sort the objects on the table by kind: put the boxes into the basket.
# Plan:
# 1. Look at the scene; check the basket is known. The boxes are the names ending in '_box':
#    red_box and gelatin_box (not the red block, the cups or mug, the plate or the saucer).
# 2. For each box not already in the basket: pick it (central lift at mid height, else adaptive
#    from above, else horizontal; each checked: the hand reached the grasp pose, attach raises on
#    empty fingers, a new look shows it rose with the hand), place it into the basket (check the
#    hand reached the place pose), release, move up.
# 3. Look again: its centre must be over the basket's footprint and its bottom below the basket's
#    rim. If not, pick and place it once more; then give up with a RuntimeError.

MOTION_ERRORS = (GraspError, PlanningError, IKError, FailureError)


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


def in_basket(name):
    # In the basket: the object's centre over the basket's footprint (an object resting inside
    # has its centre well within it, so no margin is given) and its bottom at least 1 cm below
    # the basket's top (not lying on the rim; 1 cm is above the detection noise).
    detect_objects(object_list=[name, 'basket'])
    center = get_object_center_position(name)
    bottom = get_3d_bbox(name)[2]
    basket = get_3d_bbox('basket')
    return inside_xy(center, basket) and bottom <= basket[5] - 0.01


detect_objects()
require_names('basket')
boxes = [name for name in get_object_name_list() if name.endswith('_box') and not name.startswith('cabinet')]
if not boxes:
    print('no box on the table: nothing to sort')

for name in boxes:
    if in_basket(name):
        continue  # already in the basket
    for attempt in range(2):
        pick(name)
        place(name, receptacle='basket')
        if in_basket(name):
            break
    else:
        raise RuntimeError('%s is not in the basket after two tries' % name)
