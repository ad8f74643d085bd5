# Task: clear the table by putting every object lying on it into the basket; leave the baskets and plates and saucers where they are
# Plan:
# 1. Detect everything. The things to move are all names except the table, any furniture, and the receptacles
#    (basket, plates, saucers, bowls), which stay where they are and are never grasped.
# 2. Skip what is already in the basket.
# 3. Take the things one at a time, re-detecting before each: first one with nothing standing on it (so a stack
#    is taken from the top), the highest of those first.
# 4. Grasp with the tool that fits the shape: mugs and cups by the adaptive grasp from above (rim or handle),
#    else horizontally across the body; boxes and blocks top-down at the centre, else the adaptive grasp.
#    If a grasp closes on nothing, open, back away, re-detect and try the next way.
# 5. Lift, place into the basket, release, move up.
# 6. Re-detect and check with is_object_in that it is in the basket; if not, pick it again with the other grasp
#    and place it at the basket's centre. If the basket is full or no placement works, set it back where it was
#    and raise an error.
# 7. At the end re-detect and check that every thing is still in the basket (a later one may have knocked an
#    earlier one out); put back in any that is not.


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def retreat(distance=0.1):
    # Back the empty hand away along its approach axis, else straight up.
    try:
        move_in_direction(-approach_axis(get_gripper_pose()), distance)
    except FailureError:
        try:
            move_in_direction([0, 0, 1], distance)
        except FailureError:
            pass


def lift(distance=0.1):
    try:
        move_in_direction([0, 0, 1], distance)
    except FailureError:
        pass  # move_to_pose plans its own collision-free path from here


def release(name):
    open_gripper()
    detach_object(name)
    try:
        move_in_direction([0, 0, 1], 0.1)
    except FailureError:
        retreat(0.08)


def kind_of(name):
    return name.split('_')[-1]


def grasp_ways(name):
    # Grasp tools in the order the doc-strings suggest for the object's shape.
    if kind_of(name) in ('mug', 'cup'):
        return [
            ('adaptive grasp from above (rim or handle)',
             lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])),
            ('horizontal grasp across the body',
             lambda: parse_horizontal_grasp_pose(object_name=name)),
        ]
    return [
        ('top-down grasp at the centre',
         lambda: parse_central_lift_grasp_pose(object_name=name, description='center')),
        ('adaptive grasp from above',
         lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])),
    ]


def pick(name, attempt):
    ways = grasp_ways(name)
    if attempt % 2 == 1:
        ways = ways[1:] + ways[:1]  # the retry starts with the other way
    problems = []
    for label, make_pose in ways:
        detect_objects([name])
        open_gripper()
        try:
            pose = make_pose()
        except (GraspError, FailureError) as e:
            problems.append(f'{label}: {e}')
            continue
        try:
            grasp(pose)
            close_gripper()
            attach_object(name)
        except (GraspError, FailureError) as e:
            problems.append(f'{label}: {e}')
            open_gripper()
            retreat(0.1)
            continue
        lift(0.1)
        return
    raise GraspError(f'could not pick up {name}: ' + '; '.join(problems))


def put_back(name, home):
    # Set the held object down where it stood (or aside on the table) so that nothing is left in the hand.
    try:
        move_to_pose(parse_place_pose(object_name=name, position=[home[0], home[1], home[2]]))
    except FailureError:
        move_to_pose(parse_place_pose(object_name=name, receptacle_name='table'))
    release(name)


def place_into_basket(name, attempt, home):
    def anywhere():
        return parse_place_pose(object_name=name, receptacle_name='basket')

    def centred():
        c = get_object_center_position('basket')
        return parse_place_pose(object_name=name, receptacle_name='basket', position=[c[0], c[1], c[2]])

    ways = [anywhere, centred] if attempt == 0 else [centred, anywhere]
    for make_pose in ways:
        try:
            move_to_pose(make_pose())
        except ReceptacleFullError:
            put_back(name, home)
            raise ReceptacleFullError(f'the basket is full: {name} could not be put in it (set back where it was)')
        except FailureError:
            continue  # nothing moved; try the other placement
        release(name)
        return True
    return False


def put_in_basket(name):
    detect_objects()
    home = get_object_center_position(name)
    for attempt in range(2):
        if attempt:
            detect_objects()
        if is_object_in(name, 'basket'):
            return
        pick(name, attempt)
        if not place_into_basket(name, attempt, home):
            put_back(name, home)
            continue
        detect_objects([name, 'basket'])
        if is_object_in(name, 'basket'):
            return
    raise PlacementError(f'{name} did not end up in the basket after two tries')


def stands_on(top, bottom):
    # True when `top` stands on or in `bottom`.
    try:
        return bool(is_object_in(top, bottom))
    except (UsageError, FailureError):
        t = get_3d_bbox(top)
        b = get_3d_bbox(bottom)
        cx, cy = (t[0] + t[3]) / 2, (t[1] + t[4]) / 2
        return b[0] <= cx <= b[3] and b[1] <= cy <= b[4] and t[2] >= b[5] - 0.02


STAYING_KINDS = ('basket', 'plate', 'saucer', 'bowl')

detect_objects()
items = [n for n in get_object_name_list()
         if n != 'table' and not n.startswith('cabinet') and kind_of(n) not in STAYING_KINDS]

remaining = [n for n in items if not is_object_in(n, 'basket')]
while remaining:
    detect_objects()
    remaining = [n for n in remaining if not is_object_in(n, 'basket')]
    if not remaining:
        break
    free = [n for n in remaining if not any(stands_on(o, n) for o in remaining if o != n)]
    candidates = free if free else remaining
    name = max(candidates, key=lambda n: get_3d_bbox(n)[2])
    put_in_basket(name)
    remaining.remove(name)

# Final check: every thing is in the basket, none knocked out by a later one.
detect_objects()
for name in items:
    if not is_object_in(name, 'basket'):
        put_in_basket(name)
detect_objects()
missing = [n for n in items if not is_object_in(n, 'basket')]
if missing:
    raise PlacementError('not in the basket at the end: ' + ', '.join(missing))
