# Task: open the cabinet door wide.
# Plan:
# 1. Detect everything. The cabinet has one door, cabinet.door_0, and one drawer. Its handle is the one on the
#    door's row, counted from the top with the drawer: found from the parts' heights and checked against where
#    each handle lies.
# 2. Read the door's revolute joint near its handle: hinge axis, hinge position, present and largest angle.
#    "Wide": aim for 120 degrees, or the largest angle the joint allows if that is less.
# 3. Grasp the handle horizontally (retry once with the adaptive grasp if that fails), close the gripper and
#    attach the door.
# 4. Swing the hand about the hinge by the angle still missing, in small steps, with follow_path.
# 5. Release the handle and back the hand out along its approach axis.
# 6. Detect again and read the joint: if the door is short of wide (90 degrees, or near its limit), grasp the
#    handle at its new place with the other grasp tool and swing the rest; finally check the angle.


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


def door_joint(handle):
    # The revolute joint (the hinge) nearest the handle's present centre; angles in degrees.
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')


def open_door(door, handle, wanted, enough):
    # Swing the door to `wanted` degrees (at most its limit); it must end at least at `enough` degrees.
    detect_objects()
    joint = door_joint(handle)
    target = min(wanted, joint['joint_upper'])
    enough = min(enough, target - 5)
    tools = [
        ('horizontal grasp', lambda: parse_horizontal_grasp_pose(object_name=handle)),
        ('adaptive grasp', lambda: parse_adaptive_shape_grasp_pose(
            object_name=handle,
            preferred_position=list(get_object_center_position(handle)),
            preferred_approach_direction=list(-get_plane_normal(door, get_object_center_position(handle))))),
    ]
    for label, make_grasp in tools:
        remaining = target - joint['joint_value']
        if remaining <= 2:
            break
        open_gripper()
        reached = False
        try:
            grasp(make_grasp())
            reached = True
            close_gripper()
            attach_object(door)
        except Exception as error:  # GraspError, IKError or PlanningError
            print('[door] ' + label + ' of ' + handle + ' failed: ' + str(error))
            open_gripper()
            if reached:
                back_off(0.1)
            continue
        steps = max(10, int(remaining / 3))
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                              joint_position=joint['joint_position'], n=steps, angle=remaining)
        follow_path(path)
        open_gripper()
        detach_object(door)
        back_off(0.1)
        detect_objects()
        joint = door_joint(handle)
        print('[door] ' + door + ' is open ' + str(round(float(joint['joint_value']), 1)) + ' degrees')
        if joint['joint_value'] >= enough:
            break
    if joint['joint_value'] < enough:
        raise RuntimeError(door + ' did not open far enough')
    return joint


detect_objects()
door = 'cabinet.door_0'
handle = handle_of(door)
open_door(door, handle, wanted=120, enough=90)
