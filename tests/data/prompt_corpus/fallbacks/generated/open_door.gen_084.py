# Task: swing the cabinet door open.
# Plan:
# 1. Detect everything. The cabinet is listed from the top: cabinet.door_0 above cabinet.drawer_0, so the door's handle
#    is cabinet.handle_0 (top row); check with the boxes that this handle lies on the door's front, else take the one that does.
# 2. Read the door's revolute joint near the handle; aim for 75 degrees open (less if the joint stops sooner).
# 3. Grasp the handle horizontally (else an adaptive grasp pushing in against the door front), close the gripper,
#    attach the door.
# 4. Follow an arc about the hinge from the present gripper pose, in small steps, through the angle still missing.
# 5. Let go, detach the door and back the hand out along its approach axis.
# 6. Look again and read the joint: if the door is short of the aim, grasp the handle again and swing it the rest of the
#    way once more; raise an error if it still is not open (under 40 degrees).

def approach_axis(pose):
    # The gripper's approach (z) axis, from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance=0.1):
    # Let go and draw the hand back the way it came in.
    open_gripper()
    move_in_direction(-approach_axis(get_gripper_pose()), distance)


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


def door_joint(door, handle):
    # Look again and read the door's revolute joint near its handle.
    detect_objects()
    return get_object_joint_info(object_name=door, position=get_object_center_position(handle), type='revolute')


def open_door(door, handle, wanted=75.0, enough=40.0):
    joint = door_joint(door, handle)
    goal = min(wanted, joint['joint_upper'] - 2.0)
    for attempt in (1, 2):
        still = goal - joint['joint_value']
        if still <= 3.0:
            print(f'{door} is open {joint["joint_value"]:.0f} degrees')
            return
        grab_handle(handle, door)
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=max(10, int(still / 3)), angle=still)
        try:
            follow_path(path)
        except (PlanningError, IKError) as error:
            print(f'Swinging {door} failed ({error}); letting go and looking how far it opened')
        open_gripper()
        detach_object(door)
        back_off(0.08)
        joint = door_joint(door, handle)
        opened = joint['joint_value']
        if opened >= goal - 5.0:
            print(f'Check passed: {door} is open {opened:.0f} degrees')
            return
        if attempt == 1:
            print(f'Check failed: {door} is open only {opened:.0f} of {goal:.0f} degrees; grasping the handle again to swing it further')
    if opened >= enough:
        print(f'{door} is open {opened:.0f} degrees, short of the aim of {goal:.0f} but open')
        return
    raise RuntimeError(f'{door} is open only {opened:.0f} degrees after two attempts')


detect_objects()
door = 'cabinet.door_0'
handle = handle_on(door, 'cabinet.handle_0')
open_door(door, handle)
