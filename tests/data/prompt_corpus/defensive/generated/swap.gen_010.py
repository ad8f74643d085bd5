# Task: exchange the places of the pear and the orange.
# Plan:
# 1. Detect everything; check that pear and orange are known names; remember both centres before anything moves.
# 2. Move the pear aside (20 cm towards the robot, else to the left or right, else any free spot on the table)
#    and check that it has left its place, so that the place is free.
# 3. Move the orange to where the pear was; check it is there.
# 4. Move the pear to where the orange was; check it is there.
# 5. Each move: central lift grasp, else adaptive; a failed pick or a miss is tried once more.
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


def near(name, point, tol=0.08):
    # Look again: is the object's centre within `tol` of `point` in x-y?
    detect_objects(object_list=[name])
    c = get_object_center_position(name)
    return np.linalg.norm(c[:2] - np.array(point[:2], dtype=float)) <= tol


def aside_spots(at):
    # Spots 20 cm from `at` (towards the robot, to the left, to the right), then any free spot on the table.
    return [('table', [at[0] - 0.2, at[1], at[2]]), ('table', [at[0], at[1] + 0.2, at[2]]),
            ('table', [at[0], at[1] - 0.2, at[2]]), ('table', None)]


detect_objects()
check_names(['pear', 'orange'])
pear_at = get_object_center_position('pear')
orange_at = get_object_center_position('orange')
if not transfer('pear', aside_spots(pear_at), ('central', 'adaptive'), lambda n: not near(n, pear_at)):
    raise RuntimeError('could not move the pear out of the way')
if not transfer('orange', [('table', pear_at)], ('central', 'adaptive'), lambda n: near(n, pear_at)):
    raise RuntimeError('could not move the orange to where the pear was')
if not transfer('pear', [('table', orange_at)], ('central', 'adaptive'), lambda n: near(n, orange_at)):
    raise RuntimeError('could not move the pear to where the orange was')
