# Task: place the mug into the second top drawer; the drawer is closed, open it first.
# Plan:
# 1. Detect everything; the second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1; check
#    that these and white_and_yellow_mug are known names.
# 2. Open the drawer: grasp the handle (horizontal, else adaptive from the front), attach the drawer, pull it
#    along its prismatic joint's axis, release, back away.
# 3. Look again (the drawer moved) and check its joint value; if it is not open, try once more.
# 4. Pick the mug (adaptive by its rim or handle, else from the side), place it into the open drawer, release,
#    move up.
# 5. Look again and check that the mug's centre lies within the drawer; a failed pick or a miss is tried once more.
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


def centre_in(name, region, margin=0.01):
    # Look again: does the object's centre lie within the x-y extent of `region`'s box?
    detect_objects(object_list=[name, region])
    c = get_object_center_position(name)
    box = get_3d_bbox(region)
    return box[0] - margin <= c[0] <= box[3] + margin and box[1] - margin <= c[1] <= box[4] + margin


def handle_grasp_pose(handle, method, handle_at, axis):
    if method == 'horizontal':
        return parse_horizontal_grasp_pose(object_name=handle)
    # adaptive: near the handle's centre, the hand moving in towards the cabinet (against the drawer's axis)
    return parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=handle_at,
                                           preferred_approach_direction=-axis)


def open_drawer(drawer, handle, target=0.2):
    # Pull `drawer` open by `handle`, measuring its joint before and after (looking again, since the drawer
    # moved); if it is not open far enough, try once more. True once it is open.
    for attempt in range(3):
        detect_objects()
        handle_at = get_object_center_position(handle)
        joint = get_object_joint_info(object_name='cabinet', position=handle_at, type='prismatic')
        axis = np.array(joint['joint_axis'], dtype=float)
        goal = min(target, joint['joint_upper'])
        if joint['joint_value'] >= goal - 0.03:
            return True
        if attempt == 2:
            break
        held = False
        for method in ('horizontal', 'adaptive'):
            try:
                pose = handle_grasp_pose(handle, method, handle_at, axis)
            except Exception:
                continue
            try:
                open_gripper()
                grasp(pose)
                close_gripper()
                attach_object(drawer)  # GraspError where the fingers missed the handle
            except Exception:
                open_gripper()
                move_in_direction(axis, 0.1)  # back away from the cabinet front
                continue
            held = True
            break
        if not held:
            continue
        move_in_direction(axis, goal - joint['joint_value'])  # +axis pulls it open
        open_gripper()
        detach_object(drawer)
        move_in_direction(axis, 0.05)
    return False


detect_objects()
check_names(['white_and_yellow_mug', 'cabinet.drawer_1', 'cabinet.handle_1'])
if not open_drawer('cabinet.drawer_1', 'cabinet.handle_1'):
    raise RuntimeError('the second drawer did not open')
if not transfer('white_and_yellow_mug', [('cabinet.drawer_1', None)], ('adaptive', 'horizontal'),
                lambda n: centre_in(n, 'cabinet.drawer_1'), up=0.08):
    raise RuntimeError('the mug could not be put into the second drawer')
