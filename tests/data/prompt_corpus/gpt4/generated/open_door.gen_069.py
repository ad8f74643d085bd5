# Task: swing the cabinet door open
# Plan:
# 1. Detect the objects. The cabinet has two drawers above one door, so the door is cabinet.door_0
#    and its handle is on the third row from the top: cabinet.handle_2.
# 2. Grasp the door handle, approaching against the outward normal of the door's front.
# 3. Close the gripper and attach the door.
# 4. Get the revolute joint (hinge) nearest the handle.
# 5. Follow an arc about the hinge by a positive angle, limited by how far the door opens.
# 6. Release the handle and back the gripper out along its approach axis.
detect_objects()

handle_pos = get_object_center_position('cabinet.handle_2')
door_normal = get_plane_normal('cabinet.door_0', handle_pos)
approach = -np.array(door_normal)

open_gripper()
grasp_pose = parse_adaptive_shape_grasp_pose('cabinet.handle_2', handle_pos, approach)
grasp(grasp_pose)
close_gripper()
attach_object('cabinet.door_0')

joint_info = get_object_joint_info('cabinet', handle_pos, 'revolute')
joint_axis = joint_info['joint_axis']
joint_position = joint_info['joint_position']
open_angle = min(70.0, joint_info['joint_upper'] - joint_info['joint_value'])

path = generate_arc_path_around_joint(get_gripper_pose(), joint_axis, joint_position, 30, open_angle)
follow_path(path)

open_gripper()
detach_object('cabinet.door_0')


def gripper_approach_axis(pose):
    # z axis of the gripper frame (the approach direction) from the quaternion
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


move_in_direction(-gripper_approach_axis(get_gripper_pose()), 0.1)
