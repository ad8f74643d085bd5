# Task: sort the objects on the table by kind: put the fruits into the basket.
# Plan:
# 1. Detect everything; check that basket, lime and orange are known names.
# 2. The fruits: lime and orange (the mug, the tea box and the block are not fruits; the bowl and the basket are
#    containers).
# 3. For each one not in the basket already: pick it (central lift, else adaptive), place it into the basket,
#    release, move up.
# 4. Look again and check that its centre lies within the basket; a failed pick or a miss is tried once more.
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


detect_objects()
check_names(['basket', 'lime', 'orange'])
fruits = ['lime', 'orange']
failed = []
for name in fruits:
    if centre_in(name, 'basket'):
        continue  # already there
    if not transfer(name, [('basket', None)], ('central', 'adaptive'), lambda n: centre_in(n, 'basket')):
        failed.append(name)
if failed:
    raise RuntimeError('could not put into the basket: ' + ', '.join(failed))
