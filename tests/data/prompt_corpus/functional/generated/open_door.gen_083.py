# Task: open the cabinet door wide.
# Plan:
# 1. The cabinet's rows from the top are the door, then the drawer: the door is cabinet.door_0 and its
#    handle cabinet.handle_0 (cabinet.handle_1 is the drawer's).
# 2. Read the door's revolute joint near the handle; "wide" is as far as it opens: turn it by
#    joint_upper - joint_value degrees.
# 3. Grasp the handle horizontally, close the gripper, attach the door.
# 4. Follow an arc about the hinge from the present gripper pose in small steps.
# 5. Release the handle and back the hand out along its approach axis.

DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'
DEGREES_PER_STEP = 3.0


def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def door_joint(handle):
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')


def angle_to_full_open(joint):
    return joint['joint_upper'] - joint['joint_value']


def arc_steps(angle):
    return max(2, int(np.ceil(abs(angle) / DEGREES_PER_STEP)))


def back_away(distance=0.08):
    move_in_direction(-quaternion_z_axis(get_gripper_pose()), distance)


def open_door(door, handle):
    joint = door_joint(handle)
    angle = angle_to_full_open(joint)
    if angle <= 0:
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                          joint_position=joint['joint_position'], n=arc_steps(angle), angle=angle)
    follow_path(path)
    open_gripper()
    detach_object(door)
    back_away()


def main():
    detect_objects()
    open_door(DOOR, HANDLE)


main()
