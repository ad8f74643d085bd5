# Task: exchange the places of the green apple and the red box.
# Plan:
# 1. Detect everything and remember where green_apple (not the other apple) and red_box stand before anything moves.
# 2. Move the green apple aside to a free table spot at least 12 cm from its place, so that its place is free.
# 3. Move the red box to where the green apple stood.
# 4. Move the green apple to where the red box stood.
#    Grasps for both: central top-down first, else adaptive from above, else horizontal.
# 5. After each move look again and check the object is where intended (within 5 cm); if not (say the apple rolled),
#    pick and place it once more; if that fails too, raise an error.

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


def xy_distance(p, q):
    return float(np.hypot(p[0] - q[0], p[1] - q[1]))


def move_aside(name, methods, keep_free, min_distance=0.12):
    # Put the object on a free table spot away from keep_free (its own place, which must be left empty):
    # asked as 'aside on the table' first, else 20 cm towards the robot, to the left or to the right of that place.
    # Look again and check it went; one more try if not.
    x, y, z = keep_free
    requests = [('table', None), (None, [x - 0.2, y, z]), (None, [x, y + 0.2, z]), (None, [x, y - 0.2, z])]
    for attempt in (1, 2):
        pick(name, methods)
        place(name, requests)
        detect_objects(object_list=[name])
        off = xy_distance(get_object_center_position(name), keep_free)
        if off >= min_distance:
            print(f'Check passed: {name} is {off:.2f} m away from its old place')
            return
        if attempt == 1:
            print(f'Check failed: {name} is only {off:.2f} m from its old place; picking it up and moving it aside once more')
    raise RuntimeError(f'{name} could not be moved out of its place')


def move_to_spot(name, spot, methods, tolerance=0.05):
    # Pick, place with the object's middle over spot (asked plainly, else as a place on the table there), look again and
    # check it is within tolerance of the spot; one more try, the other way of asking first, if not.
    for attempt in (1, 2):
        pick(name, methods)
        requests = [(None, spot), ('table', spot)]
        if attempt == 2:
            requests.reverse()
        place(name, requests)
        detect_objects(object_list=[name])
        off = xy_distance(get_object_center_position(name), spot)
        if off <= tolerance:
            print(f'Check passed: {name} is {off:.2f} m from its target')
            return
        if attempt == 1:
            print(f'Check failed: {name} is {off:.2f} m from its target; picking it up and placing it once more')
    raise RuntimeError(f'{name} did not end up at ({spot[0]:.2f}, {spot[1]:.2f}) after two attempts')


def where(name):
    c = get_object_center_position(name)
    return [float(c[0]), float(c[1]), float(c[2])]


detect_objects()
methods = ['central', 'adaptive', 'horizontal']
apple_at = where('green_apple')
box_at = where('red_box')
move_aside('green_apple', methods, apple_at)
move_to_spot('red_box', apple_at, methods)
move_to_spot('green_apple', box_at, methods)
