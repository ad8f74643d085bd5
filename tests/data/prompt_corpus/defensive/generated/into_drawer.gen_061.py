# Task: open the top drawer of the cabinet and put the orange into it.
# Plan:
# 1. Detect everything and check that the orange, the top drawer (cabinet.drawer_0) and its handle
#    (cabinet.handle_0) are known.
# 2. Read the drawer's prismatic joint near its handle and aim for 22 cm open (less if it opens less).
# 3. Grasp the handle horizontally (the adaptive grasp is the fallback), attach the drawer, pull along +axis by the
#    missing distance, release, back away. Detect again and read the joint anew; pull again once if it is short.
# 4. Pick the orange from above at its middle (adaptive, then horizontal grasp as fallbacks), lift it.
# 5. Place it into the open drawer (fallback: at the middle of the drawer's pulled-out part), release, move up.
# 6. Detect again and check the orange lies inside the drawer's box; if not, pick and place it once more.
DRAWER = 'cabinet.drawer_0'
HANDLE = 'cabinet.handle_0'
ITEM = 'orange'
OPEN_TO = 0.22  # metres
TOLERANCE = 0.02  # metres


def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def check_names(required):
    names = get_object_name_list()
    missing = [name for name in required if name not in names]
    if missing:
        raise RuntimeError('not found in the scene: ' + ', '.join(missing))


def back_away(distance):
    # Move back out along the hand's present approach axis.
    try:
        move_in_direction(-quaternion_z_axis(get_gripper_pose()), distance)
    except Exception as error:
        print('could not back away: %s' % error)


def try_grasps(name, attach_name, pose_makers):
    # Try each grasp in turn until the fingers hold something; attach attach_name.
    for attempt, make_pose in enumerate(pose_makers):
        moved = False
        try:
            open_gripper()
            pose = make_pose()
            moved = True
            grasp(pose)
            close_gripper()
            attach_object(attach_name)
            return
        except Exception as error:
            print('grasp attempt %d on %s failed: %s' % (attempt + 1, name, error))
            open_gripper()
            if moved:
                back_away(0.1)
    raise RuntimeError('could not grasp ' + name)


def grasp_handle(handle, part):
    def horizontal():
        return parse_horizontal_grasp_pose(object_name=handle)

    def adaptive():
        center = get_object_center_position(handle)
        normal = get_plane_normal(part, center)
        return parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=center,
                                               preferred_approach_direction=list(-normal))

    try_grasps(handle, part, [horizontal, adaptive])


def pick(name):
    def from_above():
        return parse_central_lift_grasp_pose(object_name=name, description='center')

    def adaptive():
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])

    def horizontal():
        return parse_horizontal_grasp_pose(object_name=name)

    try_grasps(name, name, [from_above, adaptive, horizontal])
    move_in_direction([0, 0, 1], 0.15)


def measure_drawer():
    # Look again (the drawer may have moved) and read the drawer's joint near its handle.
    detect_objects()
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(HANDLE), type='prismatic')


def pull_drawer(distance):
    grasp_handle(HANDLE, DRAWER)
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(HANDLE), type='prismatic')
    try:
        move_in_direction(joint['joint_axis'], distance)
    except Exception as error:
        print('pulling the drawer failed: %s' % error)
    open_gripper()
    detach_object(DRAWER)
    move_in_direction(joint['joint_axis'], 0.05)


def place_in_drawer(name):
    try:
        pose = parse_place_pose(object_name=name, receptacle_name=DRAWER)
    except Exception as error:
        print('placing into %s failed: %s; trying its pulled-out middle' % (DRAWER, error))
        joint = measure_drawer()
        handle_center = get_object_center_position(HANDLE)
        spot = handle_center - np.array(joint['joint_axis']) * (joint['joint_value'] / 2.0)
        pose = parse_place_pose(object_name=name, receptacle_name=DRAWER, position=list(spot))
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def is_in_drawer(name):
    detect_objects()
    center = get_object_center_position(name)
    box = get_3d_bbox(DRAWER)
    return box[0] <= center[0] <= box[3] and box[1] <= center[1] <= box[4] and center[2] <= box[5] + 0.05


detect_objects()
check_names(['cabinet', DRAWER, HANDLE, ITEM])

# Open the top drawer: first pull, then one retry if the check shows it short.
joint = measure_drawer()
target = min(OPEN_TO, joint['joint_upper'])
for attempt in range(2):
    joint = measure_drawer()
    missing = target - joint['joint_value']
    if missing <= TOLERANCE:
        break
    pull_drawer(missing)
joint = measure_drawer()
if joint['joint_value'] < target - TOLERANCE:
    raise RuntimeError('the top drawer opened only %.3f of %.3f m' % (joint['joint_value'], target))

# Put the orange into it: first try, then one retry if the check shows it is not inside.
for attempt in range(2):
    detect_objects()
    pick(ITEM)
    place_in_drawer(ITEM)
    if is_in_drawer(ITEM):
        break
    print('the orange is not in the drawer after attempt %d' % (attempt + 1))
else:
    raise RuntimeError('could not put the orange into the top drawer')
