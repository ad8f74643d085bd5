# Task: place the brown cup into an empty plate, found by checking whether any object lies in the plate's 2D
# region on the table.
# Plan:
# 1. Detect everything; check that the plates, the lemon and brown_ceramic_cup (the brown cup) are known names.
# 2. The plates are the names with 'plate'; the other table objects are everything but the table, the cabinet
#    and the plates.
# 3. For each plate, list the objects whose centre lies within the plate's x-y box; a plate with none is empty.
#    If no plate is empty but one holds only the cup itself, the cup is already in an empty plate.
# 4. Pick the cup (adaptive by its rim, else from the side), place it onto the empty plate, release, move up.
# 5. Look again and check that the cup's centre lies within that plate; a failed pick or a miss is tried once more.
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
known = check_names(['white_ceramic_plate', 'turquoise_salad_plate', 'lemon', 'brown_ceramic_cup'])
cup = 'brown_ceramic_cup'
plates = [name for name in known if 'plate' in name]
others = [name for name in known if name != 'table' and not name.startswith('cabinet') and name not in plates]


def objects_on(plate):
    # The objects whose centre lies within the plate's 2D region (the x-y extent of its box).
    box = get_3d_bbox(plate)
    found = []
    for name in others:
        c = get_object_center_position(name)
        if box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4]:
            found.append(name)
    return found


contents = {}
for plate in plates:
    contents[plate] = objects_on(plate)
    print('%s holds: %s' % (plate, ', '.join(contents[plate]) or 'nothing'))
empty = [plate for plate in plates if not contents[plate]]
if empty:
    target = empty[0]
    if not transfer(cup, [(target, None)], ('adaptive', 'horizontal'), lambda n: centre_in(n, target)):
        raise RuntimeError('the brown cup could not be put onto ' + target)
elif [plate for plate in plates if contents[plate] == [cup]]:
    print('the brown cup already stands alone on a plate')
else:
    raise RuntimeError('no empty plate found')
