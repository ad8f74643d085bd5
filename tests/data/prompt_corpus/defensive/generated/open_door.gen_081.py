# Task: open the cabinet door wide.
# Plan:
# 1. Look at the scene. Find the door's handle: handles are numbered by row from the top, so it is
#    cabinet.handle_0 if the door is above the drawer, else cabinet.handle_1; check it lies on the door's front.
# 2. Grasp the handle horizontally (the adaptive grasp, moving in against the door, if that raises), close the
#    gripper, attach the door.
# 3. Read the revolute joint near the handle; turn the hand about the hinge along an arc to 90 degrees ("wide"),
#    or the door's limit if that is smaller.
# 4. Let go, detach, back the hand out along its approach.
# 5. Look again and read the door's angle; if it is short of 75 degrees, grasp the handle again where it is now
#    and turn the rest of the way, once.


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


def door_joint(door, handle):
    # Looks again and reads the door's revolute joint near its handle (degrees).
    detect_objects(object_list=[door, handle])
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')


def open_door(door, handle, target_angle, enough_angle):
    # Swings the door open to target_angle degrees (or its limit) about its hinge, checks the angle it reached and,
    # if short of enough_angle, grasps the handle again where it is now and turns the rest of the way, once.
    for attempt in range(2):
        joint = door_joint(door, handle)
        goal = min(target_angle, joint['joint_upper'] - 1.0)
        if joint['joint_value'] >= min(enough_angle, goal):
            return True
        if not grab_handle(handle, door):
            continue
        remaining = goal - joint['joint_value']
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                              joint_position=joint['joint_position'],
                                              n=max(10, int(remaining / 3)), angle=remaining)
        try:
            follow_path(path)
        except Exception as error:
            print('turning', door, 'stopped:', error)
        open_gripper()
        detach_object(door)
        back_off(0.08)
    joint = door_joint(door, handle)
    return joint['joint_value'] >= min(enough_angle, joint['joint_upper'] - 1.0)


def middle_height(name):
    box = get_3d_bbox(name)
    return (box[2] + box[5]) / 2.0


detect_objects()
door = 'cabinet.door_0'
# Rows are numbered from the top, drawers and doors together: the door's handle is cabinet.handle_0 when the
# door is above the drawer, else cabinet.handle_1.
if middle_height(door) > middle_height('cabinet.drawer_0'):
    rule_handle = 'cabinet.handle_0'
else:
    rule_handle = 'cabinet.handle_1'
handle = handle_of(door, rule_handle)
if not open_door(door, handle, target_angle=90.0, enough_angle=75.0):
    raise RuntimeError('the cabinet door did not open wide')
