# Task: open the cabinet door.
# Plan:
# 1. The query lists cabinet.door_0 before cabinet.drawer_0, so the door is the top row and its handle is
#    cabinet.handle_0 (checked: the handle whose height lies within the door's box).
# 2. Read the door's revolute joint near the handle: axis, a point on it, present opening, upper limit.
# 3. Grasp the handle horizontally, close, attach the door, follow an arc about the hinge from the present
#    gripper pose by the angle from the present opening to min(80 degrees, upper limit - 2).
# 4. Release, detach, back the hand out along its approach axis.
# 5. Detect again and print how far the door is open.


def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


def handle_of(part, default):
    # The handle whose centre height lies within the part's box; the numbering rule's answer otherwise.
    pbox = get_3d_bbox(part)
    found = [n for n in get_object_name_list()
             if n.startswith('cabinet.handle_') and pbox[2] <= get_object_center_position(n)[2] <= pbox[5]]
    if len(found) == 1:
        if found[0] != default:
            print('by height the handle of', part, 'is', found[0], 'not', default)
        return found[0]
    return default


detect_objects()
door = 'cabinet.door_0'
handle = handle_of(door, 'cabinet.handle_0')
joint = get_object_joint_info(object_name=door, position=get_object_center_position(handle), type='revolute')
goal = min(80.0, joint['joint_upper'] - 2.0)
angle = goal - joint['joint_value']
print('door open', round(float(joint['joint_value']), 1), 'degrees; upper', round(float(joint['joint_upper']), 1),
      '; turning', round(float(angle), 1))

if angle > 2.0:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                          joint_position=joint['joint_position'], n=25, angle=angle)
    follow_path(path)
    open_gripper()
    detach_object(door)
    back = -np.array(quaternion_z_axis(get_gripper_pose()))
    move_in_direction(back, 0.08)

detect_objects()
joint = get_object_joint_info(object_name=door, position=get_object_center_position(handle), type='revolute')
print('door now open', round(float(joint['joint_value']), 1), 'degrees')
