# Task: place the plum beside the lemon.
# Plan:
# 1. Detect everything; check that plum and lemon are known names.
# 2. Measure both: the spot beside the lemon is its centre moved along y (left/right) by half the lemon's width
#    plus half the plum's width plus 3 cm, on the side the plum is on now; the other side is the fallback.
# 3. Pick the plum (central lift, else adaptive), place it on the table at that spot, release, move up.
# 4. Look again: the plum must rest on the table next to the lemon; a failed pick or a miss is tried once more
#    (measuring the lemon anew).
UP = [0, 0, 1]


def check_names(names):
    # Stop before anything moves if a name from the query is not one the robot knows.
    known = get_object_name_list()
    missing = [name for name in names if name not in known]
    if missing:
        raise RuntimeError('not in the scene: ' + ', '.join(missing))
    return known


def grasp_pose_for(name, method):
    if method == 'central':
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    if method == 'horizontal':
        return parse_horizontal_grasp_pose(object_name=name)
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, methods):
    # Try the grasp tools in `methods` in turn; True once the object is held and lifted.
    for method in methods:
        try:
            pose = grasp_pose_for(name, method)
        except Exception:
            continue  # this tool finds no grasp here: try the next one
        try:
            open_gripper()
            grasp(pose)
            close_gripper()
            attach_object(name)  # GraspError where the fingers closed on nothing
        except Exception:
            open_gripper()
            move_in_direction(UP, 0.1)
            detect_objects(object_list=[name])  # it may have been nudged: look again
            continue
        move_in_direction(UP, 0.1)
        return True
    return False


def release(name, up=0.1):
    open_gripper()
    detach_object(name)
    move_in_direction(UP, up)


def place(name, targets, up=0.1):
    # `targets`: (receptacle, position) pairs, tried in order. Where none works, the object is set down aside
    # on the table, so that the hand is free for a retry, and False is returned.
    for receptacle, position in targets:
        try:
            move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
        except Exception:
            continue  # PlacementError, IKError or PlanningError: try the next target
        release(name, up)
        return True
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='table'))
    release(name)
    return False


def transfer(name, targets, methods, check, up=0.1):
    # Pick, place, then verify with `check`; a failed pick or a wrong placement is tried once more.
    for attempt in range(2):
        detect_objects(object_list=[name])
        if not pick(name, methods):
            print('attempt %d: could not pick %s' % (attempt + 1, name))
            continue
        if place(name, targets, up) and check(name):
            return True
        print('attempt %d: %s did not end up where it should' % (attempt + 1, name))
    return False


def spots_beside(name, anchor):
    # Spots on the table beside `anchor`: its centre moved along y by half of each one's width plus 3 cm,
    # first on the side `name` is on now, then on the other side. Returns the spots and that distance.
    detect_objects(object_list=[name, anchor])
    a = get_object_center_position(anchor)
    n = get_object_center_position(name)
    a_box = get_3d_bbox(anchor)
    n_box = get_3d_bbox(name)
    gap = (a_box[4] - a_box[1]) / 2 + (n_box[4] - n_box[1]) / 2 + 0.03
    side = 1.0 if n[1] >= a[1] else -1.0
    spots = [('table', [a[0], a[1] + side * gap, a[2]]), ('table', [a[0], a[1] - side * gap, a[2]])]
    return spots, gap


def is_beside(name, anchor, gap):
    # Look again: the object rests on the table, its centre no farther from the anchor's than planned + 8 cm.
    detect_objects(object_list=[name, anchor])
    d = np.linalg.norm(get_object_center_position(name)[:2] - get_object_center_position(anchor)[:2])
    on_table = get_3d_bbox(name)[2] <= get_3d_bbox('table')[5] + 0.02
    return on_table and d <= gap + 0.08


detect_objects()
check_names(['plum', 'lemon'])
done = False
for attempt in range(2):
    spots, gap = spots_beside('plum', 'lemon')
    if not pick('plum', ('central', 'adaptive')):
        print('attempt %d: could not pick the plum' % (attempt + 1))
        continue
    if place('plum', spots) and is_beside('plum', 'lemon', gap):
        done = True
        break
    print('attempt %d: the plum is not beside the lemon' % (attempt + 1))
if not done:
    raise RuntimeError('the plum could not be placed beside the lemon')
