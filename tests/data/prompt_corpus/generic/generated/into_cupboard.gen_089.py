# Task: open the cabinet door and put the peach in the cupboard behind it
# Plan:
# 1. Detect everything. The door is the name 'cabinet.door_k'; its handle: rows are numbered from the top,
#    drawers and doors together, so sort them by height (highest first) and the k-th row has 'cabinet.handle_k'.
# 2. Read the door's revolute joint near its handle; grasp the handle horizontally, attach the door and follow
#    an arc about the hinge up to 90 degrees (at most its limit; 40 or more is needed to put things behind it).
# 3. Release the handle, back out along the approach, detect the door again (it moved).
# 4. Grasp the peach level (horizontal grasp), lift it a little, place it into the compartment behind the door.
# 5. Release it (the hand backs out the way it came), then move further back along the approach.
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


def pick_level(name, lift=0.03):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put_behind_door(name, door):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=door))
    open_gripper()
    detach_object(name)
    move_in_direction(-approach_axis(get_gripper_pose()), 0.1)


detect_objects()
names = get_object_name_list()
door = [n for n in names if n.startswith('cabinet.door_')][0]
swing_door(door, handle_of(door, names), target_degrees=90)
detect_objects(object_list=[door])
for name in ['peach']:
    pick_level(name)
    put_behind_door(name, door)
