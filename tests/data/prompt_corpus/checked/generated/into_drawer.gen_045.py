# Task: open the second drawer of the cabinet and put the white mug into it.
# Plan:
# 1. Detect everything. Drawers are numbered from the top, so the second drawer is cabinet.drawer_1. Its handle is
#    the one on the second row from the top (cabinet.handle_1 here); check that it lies on the drawer's front.
# 2. Open the drawer: grasp the handle horizontally (retry once with the adaptive grasp if that fails), attach the
#    drawer, pull along its prismatic joint's axis (out of the cabinet) to about 25 cm or as far as it goes,
#    release and back away. Detect again and check the joint value says it is open that far.
# 3. Pick the white mug: the adaptive grasp from above (by its rim); if that fails, or the cameras do not see the
#    mug rise with the hand, let go and retry once with the horizontal grasp.
# 4. Place the mug into the open drawer with parse_place_pose, release it and move up.
# 5. Check with a fresh detection that the mug lies within the drawer's box; if not, pick and place it once more.


def approach_axis(pose):
    # The gripper's approach (z) axis, from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance=0.1):
    # Move the hand straight back along its approach axis.
    move_in_direction(-approach_axis(get_gripper_pose()), distance)


def handle_of(part):
    # Handles are numbered by row from the top, drawers and doors counted together: the part's rank by height
    # gives its handle. Check that this handle lies on the part's front; if not, take the one that does.
    names = get_object_name_list()
    parts = [n for n in names if n.startswith('cabinet.drawer_') or n.startswith('cabinet.door_')]
    parts.sort(key=lambda n: -(get_3d_bbox(n)[2] + get_3d_bbox(n)[5]))
    handles = [n for n in names if n.startswith('cabinet.handle_')]
    box = get_3d_bbox(part)

    def on_part(handle):
        c = get_object_center_position(handle)
        return box[1] - 0.02 <= c[1] <= box[4] + 0.02 and box[2] - 0.02 <= c[2] <= box[5] + 0.02

    by_row = 'cabinet.handle_' + str(parts.index(part))
    if by_row in handles and on_part(by_row):
        return by_row
    for handle in handles:
        if on_part(handle):
            print('[handle] using ' + handle + ' for ' + part + ': it lies on its front')
            return handle
    raise RuntimeError('no handle found on ' + part)


def drawer_joint(handle):
    # The prismatic joint nearest the handle's present centre.
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def open_drawer(drawer, handle, opening):
    # Pull the drawer out until it is open by `opening` metres (or nearly as far as it goes).
    detect_objects()
    joint = drawer_joint(handle)
    target = min(opening, joint['joint_upper'] - 0.005)
    tools = [
        ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name=handle)),
        ('adaptive grasp', lambda: parse_adaptive_shape_grasp_pose(
            object_name=handle,
            preferred_position=list(get_object_center_position(handle)),
            preferred_approach_direction=list(-np.array(joint['joint_axis'])))),
    ]
    for label, make_grasp in tools:
        remaining = target - joint['joint_value']
        if remaining <= 0.01:
            break
        open_gripper()
        reached = False
        try:
            grasp(make_grasp())
            reached = True
            close_gripper()
            attach_object(drawer)
        except Exception as error:  # GraspError, IKError or PlanningError
            print('[drawer] ' + label + ' of ' + handle + ' failed: ' + str(error))
            open_gripper()
            if reached:
                back_off(0.1)
            continue
        move_in_direction(joint['joint_axis'], remaining)
        open_gripper()
        detach_object(drawer)
        move_in_direction(joint['joint_axis'], 0.05)
        detect_objects()
        joint = drawer_joint(handle)
        print('[drawer] ' + drawer + ' is open ' + str(round(float(joint['joint_value']), 3)) + ' m')
        if joint['joint_value'] >= target - 0.03:
            break
    if joint['joint_value'] < target - 0.03:
        raise RuntimeError(drawer + ' did not open far enough')
    return joint


def grasp_options(name):
    # For a mug: the adaptive grasp from above (rim) first, the horizontal grasp to retry with.
    return [
        ('adaptive grasp', lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])),
        ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name=name)),
    ]


def pick(name):
    # Grasp, attach and lift the object; it counts as picked only if the cameras see it rise with the hand.
    for label, make_grasp in grasp_options(name):
        detect_objects([name])
        z_before = get_object_center_position(name)[2]
        open_gripper()
        reached = False
        try:
            grasp(make_grasp())
            reached = True
            close_gripper()
            attach_object(name)
        except Exception as error:  # GraspError, IKError or PlanningError
            print('[pick] ' + label + ' of ' + name + ' failed: ' + str(error))
            open_gripper()
            if reached:
                back_off(0.1)
            continue
        move_in_direction([0, 0, 1], 0.1)
        detect_objects([name])
        if get_object_center_position(name)[2] > z_before + 0.05:
            return label
        print('[pick] ' + name + ' did not rise with the hand after the ' + label + '; letting go')
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], 0.05)
    raise RuntimeError('could not pick up ' + name + ' with either grasp tool')


def place(name, receptacle):
    # Set the held object down where parse_place_pose says, let go and move up.
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.08)


def in_drawer(name, drawer):
    # Fresh look: the object's centre is within the drawer's box, its bottom between the drawer's floor and top.
    detect_objects([name, drawer])
    centre = get_object_center_position(name)
    box = get_3d_bbox(drawer)
    bottom = get_3d_bbox(name)[2]
    inside = box[0] <= centre[0] <= box[3] and box[1] <= centre[1] <= box[4]
    return bool(inside and box[2] - 0.02 <= bottom <= box[5])


def transfer(name, drawer):
    # Pick and place, then check the result; one more try if the check fails.
    for attempt in range(2):
        pick(name)
        place(name, drawer)
        if in_drawer(name, drawer):
            return
        print('[check] ' + name + ' is not in ' + drawer + ' after try ' + str(attempt + 1))
    raise RuntimeError(name + ' could not be put into ' + drawer)


detect_objects()
drawer = 'cabinet.drawer_1'
handle = handle_of(drawer)
open_drawer(drawer, handle, 0.25)
transfer('white_mug', drawer)
