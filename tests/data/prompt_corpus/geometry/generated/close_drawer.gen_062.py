# Task: close the top drawer of the cabinet.
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0 (drawers are numbered from the top).
# 2. Read the drawer's prismatic joint near the handle: joint_value is how far it is open, in metres.
# 3. If it is open, grasp the handle horizontally, close the gripper and attach the drawer.
# 4. Push along -axis by exactly how far it is open, so it ends shut.
# 5. Release the handle and back the hand away along +axis with a Pose built from the present gripper pose.
def shifted_pose(pose, direction, distance):
    # A copy of pose, moved by distance metres along direction, same orientation.
    d = np.array(direction, dtype=float)
    d = d / np.linalg.norm(d)
    new_pose = Pose()
    new_pose.position.x = pose.position.x + distance * d[0]
    new_pose.position.y = pose.position.y + distance * d[1]
    new_pose.position.z = pose.position.z + distance * d[2]
    new_pose.orientation.x = pose.orientation.x
    new_pose.orientation.y = pose.orientation.y
    new_pose.orientation.z = pose.orientation.z
    new_pose.orientation.w = pose.orientation.w
    return new_pose


detect_objects()
handle_position = get_object_center_position('cabinet.handle_0')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='prismatic')
axis = np.array(joint['joint_axis'], dtype=float)
opening = joint['joint_value']  # metres the drawer stands out

if opening > 0.005:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
    close_gripper()
    attach_object('cabinet.drawer_0')
    move_in_direction(axis, -opening)
    open_gripper()
    detach_object('cabinet.drawer_0')
    move_to_pose(shifted_pose(get_gripper_pose(), axis, 0.06))
