# Task: push the open drawer shut.
# Plan:
# 1. Detect everything and check that both drawers and their handles are known: cabinet.handle_0 is the top
#    drawer's handle, cabinet.handle_1 the second drawer's (cabinet.handle_2 belongs to the door, not a drawer).
# 2. Read each drawer's prismatic joint near its handle; the open drawer is the one pulled out farthest.
# 3. Grasp its handle horizontally (the adaptive grasp is the fallback), close the gripper, attach the drawer,
#    and push along -axis by as far as it is open.
# 4. Release the handle and back away along +axis.
# 5. Detect again and read the joint anew; if the drawer is still open by more than 1 cm, push it again, once.
DRAWERS = {'cabinet.drawer_0': 'cabinet.handle_0', 'cabinet.drawer_1': 'cabinet.handle_1'}
CLOSED = 0.01  # metres


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


def grasp_handle(handle, part):
    # Grasp the handle and attach the part it moves; horizontal grasp first, adaptive grasp as fallback.
    def horizontal():
        return parse_horizontal_grasp_pose(object_name=handle)

    def adaptive():
        center = get_object_center_position(handle)
        normal = get_plane_normal(part, center)
        return parse_adaptive_shape_grasp_pose(object_name=handle, preferred_position=center,
                                               preferred_approach_direction=list(-normal))

    for attempt, make_pose in enumerate([horizontal, adaptive]):
        moved = False
        try:
            open_gripper()
            pose = make_pose()
            moved = True
            grasp(pose)
            close_gripper()
            attach_object(part)
            return
        except Exception as error:
            print('grasp attempt %d on %s failed: %s' % (attempt + 1, handle, error))
            open_gripper()
            if moved:
                back_away(0.1)
    raise RuntimeError('could not grasp ' + handle)


def measure_drawer(handle):
    # Look again (the drawer may have moved) and read the drawer's joint near its handle.
    detect_objects()
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def push_shut(drawer, handle, joint):
    grasp_handle(handle, drawer)
    try:
        move_in_direction(joint['joint_axis'], -joint['joint_value'])
    except Exception as error:
        print('pushing the drawer failed: %s' % error)
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


detect_objects()
check_names(['cabinet'] + list(DRAWERS.keys()) + list(DRAWERS.values()))
openings = {drawer: measure_drawer(handle)['joint_value'] for drawer, handle in DRAWERS.items()}
drawer = max(openings, key=openings.get)
handle = DRAWERS[drawer]

if openings[drawer] <= CLOSED:
    print('no drawer is open; nothing to do')
else:
    # First push, then one retry if the check shows the drawer still open.
    for attempt in range(2):
        joint = measure_drawer(handle)
        if joint['joint_value'] <= CLOSED:
            break
        push_shut(drawer, handle, joint)
    joint = measure_drawer(handle)
    if joint['joint_value'] > CLOSED:
        raise RuntimeError('%s is still open by %.3f m' % (drawer, joint['joint_value']))
