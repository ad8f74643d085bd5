# Task: open the cabinet door.
# Plan:
# 1. The cabinet has two drawers above one door: the door is cabinet.door_0, its handle cabinet.handle_2.
# 2. Helpers: read the gripper's approach axis, and open a door by its handle.
# 3. To open the door: grasp the handle horizontally, close the gripper, attach the door.
# 4. Get the door's revolute joint near the handle and follow an arc about the hinge.
# 5. Release the handle and back away along the gripper's approach axis.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_away(distance):
    # Move the hand straight back, against its approach direction.
    move_in_direction(-quaternion_z_axis(get_gripper_pose()), distance)


def open_door(door, handle, angle=60):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
    turn = min(angle, joint['joint_upper'] - joint['joint_value'])
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=turn)
    follow_path(path)
    open_gripper()
    detach_object(door)
    back_away(0.08)


detect_objects()
open_door('cabinet.door_0', 'cabinet.handle_2')
