# Task: put the blue mug into the second drawer; the drawer is closed, so open it first.
# Plan:
# 1. Look at the scene. The second drawer from the top is cabinet.drawer_1; by the numbering rule (two drawers
#    above a door) its handle is cabinet.handle_1 - check that this handle lies on the drawer's front.
# 2. Grasp the handle horizontally (the adaptive grasp if that raises), close, attach the drawer.
# 3. Read the drawer's prismatic joint near the handle and pull along its axis to about 25 cm (or its limit).
# 4. Let go, detach, back away along the axis; look again and check how far the drawer is open; if short,
#    grasp and pull once more.
# 5. Look again, pick the blue mug by its rim from above (adaptive grasp), else top-down, else horizontally; lift.
# 6. Place it into the open drawer and let go; look again and check that the mug is over the drawer; retry once.


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance):
    # Moves the hand straight back along its approach axis (after a failed grasp or after letting go).
    try:
        move_in_direction(-approach_axis(get_gripper_pose()), distance)
    except Exception as error:
        print('could not back off:', error)


def top_grasp(name):
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def rim_grasp(name):
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def side_grasp(name):
    return parse_horizontal_grasp_pose(object_name=name)


def pick(name, grasp_tools, lift=0.1):
    # Tries the grasp tools in order, looking again before each try, and falls back to the next tool when one
    # raises or the fingers close on nothing; two rounds at most. True when the object is held and lifted.
    for attempt in range(2):
        for make_grasp in grasp_tools:
            detect_objects(object_list=[name])
            open_gripper()
            try:
                grasp_pose = make_grasp(name)
            except Exception as error:
                print('no', make_grasp.__name__, 'for', name, ':', error)
                continue
            reached = False
            try:
                grasp(grasp_pose)
                reached = True
                close_gripper()
                attach_object(name)
            except Exception as error:
                print(make_grasp.__name__, 'of', name, 'failed:', error)
                open_gripper()
                if reached:
                    back_off(0.1)
                continue
            try:
                move_in_direction([0, 0, 1], lift)
            except Exception as error:
                print('could not lift', name, ':', error)
            return True
    return False


def set_down_on_table(name):
    # Frees the hand: sets the held object down on a free spot of the table.
    try:
        move_to_pose(parse_place_pose(object_name=name, receptacle_name='table'))
    except Exception as error:
        print('could not set', name, 'down on the table:', error)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def place(name, receptacle=None, position=None):
    # Moves the held object to its place and lets go; if that raises, looks again and tries once more, else sets
    # the object down on the table. True when it was let go at its place.
    for attempt in range(2):
        try:
            place_pose = parse_place_pose(object_name=name, receptacle_name=receptacle, position=position)
            move_to_pose(place_pose)
        except Exception as error:
            print('placing', name, 'failed:', error)
            detect_objects()
            continue
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], 0.1)
        return True
    set_down_on_table(name)
    return False


def over(name, support, margin=0.01):
    # True when the object's centre lies above the support's box in x and y.
    centre = get_object_center_position(name)
    box = get_3d_bbox(support)
    return box[0] - margin <= centre[0] <= box[3] + margin and box[1] - margin <= centre[1] <= box[4] + margin


def put(name, receptacle, grasp_tools, check=over, lift=0.1):
    # Pick and place, then look again and check where the object ended up; one retry if it is not there.
    for attempt in range(2):
        if not pick(name, grasp_tools, lift):
            return False
        placed = place(name, receptacle=receptacle)
        detect_objects(object_list=[name, receptacle])
        if placed and check(name, receptacle):
            return True
        print(name, 'did not end up in/on', receptacle, '- trying once more')
    return False


def handle_of(part, rule_handle):
    # The handle on the part's front. By the numbering rule it is rule_handle; keep that when its centre lies on the
    # part's front (inside the part's box in y and z), else take the handle that does, nearest the part's middle.
    box = np.array(get_3d_bbox(part))
    middle = (box[:3] + box[3:]) / 2.0
    best, best_score = rule_handle, None
    for name in get_object_name_list():
        if not name.startswith('cabinet.handle_'):
            continue
        centre = np.array(get_object_center_position(name))
        inside = box[1] - 0.03 <= centre[1] <= box[4] + 0.03 and box[2] - 0.03 <= centre[2] <= box[5] + 0.03
        if inside and name == rule_handle:
            return rule_handle
        score = abs(centre[2] - middle[2]) + abs(centre[1] - middle[1]) + (0.0 if inside else 10.0)
        if best_score is None or score < best_score:
            best, best_score = name, score
    print('using', best, 'for', part, 'instead of', rule_handle)
    return best


def grab_handle(handle, part):
    # Grasps the handle and attaches its drawer or door: the horizontal grasp first, the adaptive grasp (moving in
    # against the front) if that raises or the fingers close on nothing. True when attached.
    detect_objects(object_list=[part, handle])
    centre = np.array(get_object_center_position(handle))
    try:
        inward = -np.array(get_plane_normal(object_name=part, position=centre))
    except Exception as error:
        print('no plane normal for', part, ':', error)
        inward = np.array([1.0, 0.0, 0.0])
    makers = [
        lambda: parse_horizontal_grasp_pose(object_name=handle),
        lambda: parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=list(centre),
                                                preferred_approach_direction=list(inward)),
    ]
    for make_grasp in makers:
        open_gripper()
        try:
            grasp_pose = make_grasp()
        except Exception as error:
            print('no grasp of', handle, ':', error)
            continue
        reached = False
        try:
            grasp(grasp_pose)
            reached = True
            close_gripper()
            attach_object(part)
            return True
        except Exception as error:
            print('grasping', handle, 'failed:', error)
            open_gripper()
            if reached:
                back_off(0.08)
    return False


def drawer_joint(drawer, handle):
    # Looks again and reads the drawer's prismatic joint near its handle.
    detect_objects(object_list=[drawer, handle])
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def open_drawer(drawer, handle, wanted=0.25):
    # Pulls the drawer out to `wanted` metres (or its limit), checks how far it moved and tries once more if short.
    for attempt in range(2):
        joint = drawer_joint(drawer, handle)
        goal = min(wanted, joint['joint_upper'] - 0.01)
        if joint['joint_value'] >= goal - 0.03:
            return True
        if not grab_handle(handle, drawer):
            continue
        axis = np.array(joint['joint_axis'])
        try:
            move_in_direction(axis, goal - joint['joint_value'])
        except Exception as error:
            print('pulling', drawer, 'stopped:', error)
        open_gripper()
        detach_object(drawer)
        move_in_direction(axis, 0.05)
    joint = drawer_joint(drawer, handle)
    return joint['joint_value'] >= min(wanted, joint['joint_upper'] - 0.01) - 0.05


detect_objects()
drawer = 'cabinet.drawer_1'
handle = handle_of(drawer, 'cabinet.handle_1')
if not open_drawer(drawer, handle):
    raise RuntimeError('the second drawer did not open far enough')
detect_objects()
if not put('blue_mug', drawer, [rim_grasp, top_grasp, side_grasp]):
    raise RuntimeError('the blue mug did not end up in the second drawer')
