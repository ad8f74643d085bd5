# Task: put the peach into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. Detect everything. The cabinet has two drawers above a door, so the second drawer is cabinet.drawer_1 and its
#    handle cabinet.handle_1 (second row from the top); check with the boxes that this handle lies on that drawer's front.
# 2. Open the drawer: grasp the handle horizontally (else an adaptive grasp pushing in against the drawer front),
#    close the gripper, attach the drawer, pull along its prismatic joint axis to about 22 cm (not past its limit),
#    let go and back away along the axis.
# 3. Look again and read the joint: if the drawer is not open as far as wanted, grasp the handle again and pull the rest.
# 4. Pick the peach: a central top-down grasp first; if that fails, an adaptive grasp from above, then a horizontal one.
# 5. Place it into the open drawer: ask for a place in the drawer; if that fails, in the drawer at the middle of its
#    pulled-out part, then simply at that position (it rests on the drawer beneath). Let go and move up.
# 6. Look again and check that the peach is in the drawer; if not, pick and place it once more, else raise an error.

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


def handle_on(part, default):
    # The handle whose centre lies on the part's front (within its box in y and z); the naming rule's
    # choice is checked first and kept when it fits.
    box = get_3d_bbox(part)
    handles = [n for n in get_object_name_list() if n.startswith('cabinet.handle_')]
    for handle in [default] + [h for h in handles if h != default]:
        c = get_object_center_position(handle)
        if box[1] - 0.02 <= c[1] <= box[4] + 0.02 and box[2] - 0.02 <= c[2] <= box[5] + 0.02:
            if handle != default:
                print(f'{default} does not lie on {part} by the boxes; using {handle} instead')
            return handle
    print(f'No handle lies on {part} by the boxes; keeping {default} by the naming rule')
    return default


def grab_handle(handle, part):
    # Grasp the handle and attach the drawer or door: horizontal grasp first, then an adaptive grasp that moves in
    # against the front. Raise the last error if neither holds.
    handle_at = get_object_center_position(handle)
    inward = -np.array(get_plane_normal(part, handle_at))
    last_error = None
    for method in ('horizontal', 'adaptive'):
        reached = False
        try:
            open_gripper()
            if method == 'horizontal':
                pose = parse_horizontal_grasp_pose(object_name=handle)
            else:
                pose = parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=[float(v) for v in handle_at], preferred_approach_direction=[float(v) for v in inward])
            grasp(pose)
            reached = True
            close_gripper()
            attach_object(part)
            print(f'Holding {part} by {handle} with the {method} grasp')
            return
        except (GraspError, IKError, PlanningError) as error:
            last_error = error
            following = 'the adaptive grasp' if method == 'horizontal' else 'nothing left to try'
            print(f'Grasping {handle} with the {method} grasp failed ({error}); next: {following}')
            if reached:
                back_off(0.08)
    raise last_error


def drawer_joint(drawer, handle):
    # Look again and read the drawer's prismatic joint near its handle.
    detect_objects()
    return get_object_joint_info(object_name=drawer, position=get_object_center_position(handle), type='prismatic')


def open_drawer(drawer, handle, wanted=0.22):
    joint = drawer_joint(drawer, handle)
    goal = min(wanted, 0.95 * joint['joint_upper'])
    for attempt in (1, 2):
        still = goal - joint['joint_value']
        if still <= 0.01:
            print(f'{drawer} is open {joint["joint_value"]:.2f} m already')
            return joint
        grab_handle(handle, drawer)
        move_in_direction(joint['joint_axis'], still)
        open_gripper()
        detach_object(drawer)
        move_in_direction(joint['joint_axis'], 0.05)
        joint = drawer_joint(drawer, handle)
        opened = joint['joint_value']
        if opened >= goal - 0.02:
            print(f'Check passed: {drawer} is open {opened:.2f} m')
            return joint
        if attempt == 1:
            print(f'Check failed: {drawer} is open only {opened:.2f} m of {goal:.2f} m; grasping the handle again to pull the rest')
    raise RuntimeError(f'{drawer} did not open to {goal:.2f} m after two attempts')


def in_drawer(name, drawer, handle, joint):
    # In the drawer's box (as for any container), or, should the drawer's box be its front only: within the front's
    # width and height, behind the handle and no deeper than the pulled-out part.
    c = get_object_center_position(name)
    o = get_3d_bbox(name)
    d = get_3d_bbox(drawer)
    over = d[0] - 0.01 <= c[0] <= d[3] + 0.01 and d[1] - 0.01 <= c[1] <= d[4] + 0.01
    level = d[2] - 0.02 <= o[2] <= d[5] + 0.02
    if over and level:
        return True
    depth = float(np.dot(np.array(c) - np.array(get_object_center_position(handle)), np.array(joint['joint_axis'])))
    across = d[1] - 0.01 <= c[1] <= d[4] + 0.01
    return across and level and -(joint['joint_value'] + 0.05) <= depth <= 0.0


def put_in_drawer(name, drawer, handle, joint, methods):
    for attempt in (1, 2):
        pick(name, methods)
        # The middle of the pulled-out part: from the handle, back along the axis by half the opening and the
        # handle's standoff (about 3 cm).
        middle = np.array(get_object_center_position(handle)) - np.array(joint['joint_axis']) * (joint['joint_value'] / 2 + 0.03)
        spot = [float(middle[0]), float(middle[1]), float(middle[2])]
        requests = [(drawer, None), (drawer, spot), (None, spot)]
        if attempt == 2:
            requests = [requests[1], requests[0], requests[2]]
        place(name, requests, lift=0.08)
        detect_objects(object_list=[name, drawer, handle])
        if in_drawer(name, drawer, handle, joint):
            print(f'Check passed: {name} is in {drawer}')
            return
        if attempt == 1:
            print(f'Check failed: {name} is not in {drawer}; picking it up and placing it once more, at the middle first')
    raise RuntimeError(f'{name} did not end up in {drawer} after two attempts')


detect_objects()
drawer = 'cabinet.drawer_1'
handle = handle_on(drawer, 'cabinet.handle_1')
joint = open_drawer(drawer, handle)
detect_objects()
put_in_drawer('peach', drawer, handle, joint, ['central', 'adaptive', 'horizontal'])
