# Task: open the cabinet door wide
# Plan:
# 1. Detect everything. The door is the name 'cabinet.door_k'; its handle: rows are numbered from the top,
#    drawers and doors together, so sort them by height (highest first) and the k-th row has 'cabinet.handle_k'.
# 2. Read the door's revolute joint near the handle. "Wide": open it to its limit, but at most 120 degrees.
# 3. Grasp the handle horizontally, attach the door, follow an arc about the hinge by the missing angle
#    in small steps.
# 4. Release the handle and back out along the approach.
def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def handle_of(part, names):
    rows = [n for n in names if n.startswith('cabinet.drawer_') or n.startswith('cabinet.door_')]
    rows.sort(key=lambda n: -get_object_center_position(n)[2])
    return 'cabinet.handle_%d' % rows.index(part)


def swing_door(door, handle, target_degrees):
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
    angle = min(target_degrees, joint['joint_upper']) - joint['joint_value']
    if angle <= 0:
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                          joint_position=joint['joint_position'], n=max(10, int(angle / 3)), angle=angle)
    follow_path(path)
    open_gripper()
    detach_object(door)
    move_in_direction(-approach_axis(get_gripper_pose()), 0.08)


detect_objects()
names = get_object_name_list()
for door in [n for n in names if n.startswith('cabinet.door_')][:1]:
    swing_door(door, handle_of(door, names), target_degrees=120)
