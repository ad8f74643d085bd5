# Task: put the wooden bar into the cabinet behind its door; the door is closed, open it first.
# Plan:
# 1. The cabinet's rows from the top are the door, then the drawer: the door is cabinet.door_0, its handle
#    cabinet.handle_0.
# 2. Read the door's revolute joint near the handle and open it as far as it goes (joint_upper - joint_value
#    degrees): grasp the handle horizontally, attach the door, follow an arc about the hinge, release,
#    back the hand out along its approach axis.
# 3. Detect again and check that the door stands open at least 40 degrees (needed to place behind it).
# 4. Grasp the wooden bar level (horizontal grasp, from the robot's side), lift it.
# 5. Get the place pose in the compartment behind the door, move there, open the gripper (the hand backs
#    out), detach the bar, and back a little further out.

DOOR = 'cabinet.door_0'
HANDLE = 'cabinet.handle_0'
ITEM = 'wooden_bar'
MIN_DOOR_ANGLE = 40.0
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


def require_open(handle, minimum):
    value = door_joint(handle)['joint_value']
    if value < minimum:
        raise FailureError('the door opened only %.0f degrees, %.0f needed to reach behind it' % (value, minimum))


def pick_level(name, lift=0.1):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name, approach_direction=[1, 0, 0]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place_behind_door(name, door):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=door))
    open_gripper()
    detach_object(name)
    back_away(0.05)


def main():
    detect_objects()
    open_door(DOOR, HANDLE)
    detect_objects()
    require_open(HANDLE, MIN_DOOR_ANGLE)
    pick_level(ITEM)
    place_behind_door(ITEM, DOOR)


main()
