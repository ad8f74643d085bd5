# Task: put the green block into the green bowl.
# Plan:
# 1. Detect everything. The block is green_block, the bowl green_bowl (the bowl stays where it is).
# 2. Pick the block: a central top-down grasp first; if that fails, an adaptive grasp from above, then a horizontal one.
# 3. Place it into the bowl: ask for a place in the bowl; if that fails, in the bowl at its centre, then simply at the
#    bowl's centre position (it then rests in the bowl beneath). Let go and move up.
# 4. Look again: the block's centre must be over the bowl and its bottom within the bowl's height.
#    If not, pick it up and place it once more (centre first); if that fails too, raise an error.

def approach_axis(pose):
    # The gripper's approach (z) axis, from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance=0.1):
    # Let go and draw the hand back the way it came in.
    open_gripper()
    move_in_direction(-approach_axis(get_gripper_pose()), distance)


def grasp_pose_for(name, method):
    if method == 'central':
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    if method == 'central_top':
        return parse_central_lift_grasp_pose(object_name=name, description='top')
    if method == 'adaptive':
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    return parse_horizontal_grasp_pose(object_name=name)


def pick(name, methods):
    # Try the grasps in order; the first that holds the object lifts it 10 cm. Raise the last error if none does.
    detect_objects(object_list=[name])
    last_error = None
    for i, method in enumerate(methods):
        reached = False
        try:
            open_gripper()
            grasp(grasp_pose_for(name, method))
            reached = True
            close_gripper()
            attach_object(name)
            move_in_direction([0, 0, 1], 0.1)
            print(f'Picked {name} with the {method} grasp')
            return
        except (GraspError, IKError, PlanningError) as error:
            last_error = error
            following = f'the {methods[i + 1]} grasp' if i + 1 < len(methods) else 'nothing left to try'
            print(f'Picking {name} with the {method} grasp failed ({error}); next: {following}')
            if reached:
                back_off()
    raise last_error


def describe(request):
    receptacle, position = request
    where = []
    if receptacle is not None:
        where.append(f'in/on {receptacle}')
    if position is not None:
        where.append(f'at ({position[0]:.2f}, {position[1]:.2f})')
    return ' '.join(where)


def place(name, requests, lift=0.1):
    # Try the place requests (receptacle, position) in order; set the object down at the first that works,
    # let go and move up. Return the index of the request used; raise the last error if none works.
    last_error = None
    for i, (receptacle, position) in enumerate(requests):
        try:
            move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
        except (PlacementError, ReceptacleFullError, IKError, PlanningError) as error:
            last_error = error
            following = describe(requests[i + 1]) if i + 1 < len(requests) else 'nothing left to try'
            print(f'Placing {name} {describe(requests[i])} failed ({error}); next: {following}')
            continue
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], lift)
        print(f'Placed {name} {describe(requests[i])}')
        return i
    raise last_error


def rests_in_or_on(name, receptacle):
    # True when the object's centre is over the receptacle's box and its bottom lies between the
    # receptacle's floor and just above its top (in a bowl or basket, or on a plate or saucer).
    c = get_object_center_position(name)
    o = get_3d_bbox(name)
    r = get_3d_bbox(receptacle)
    over = r[0] - 0.01 <= c[0] <= r[3] + 0.01 and r[1] - 0.01 <= c[1] <= r[4] + 0.01
    level = r[2] - 0.02 <= o[2] <= r[5] + 0.02
    return over and level


def put_in(name, receptacle, methods):
    # Pick, place in/on the receptacle, look again and check; one more try if the check fails.
    for attempt in (1, 2):
        pick(name, methods)
        c = get_object_center_position(receptacle)
        spot = [float(c[0]), float(c[1]), float(c[2])]
        requests = [(receptacle, None), (receptacle, spot), (None, spot)]
        if attempt == 2:
            requests = [requests[1], requests[0], requests[2]]
        place(name, requests)
        detect_objects(object_list=[name, receptacle])
        if rests_in_or_on(name, receptacle):
            print(f'Check passed: {name} is in/on {receptacle}')
            return
        if attempt == 1:
            print(f'Check failed: {name} is not in/on {receptacle}; picking it up and placing it once more, at its centre first')
    raise RuntimeError(f'{name} did not end up in/on {receptacle} after two attempts')


detect_objects()
put_in('green_block', 'green_bowl', ['central', 'adaptive', 'horizontal'])
