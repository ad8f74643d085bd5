# Task: swing the cabinet door open.
# Plan:
# 1. The query lists the door before the drawer, so the door is the top row: cabinet.door_0, its handle cabinet.handle_0.
# 2. Grasp the door's handle horizontally and attach the door.
# 3. The door turns about a revolute joint: get its axis and position near the handle.
# 4. Follow an arc about the hinge from the present gripper pose, in small steps.
# 5. Release the handle and move back out of the door's way.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='revolute')
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=60)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
pose = get_gripper_pose()
back = -np.array(quaternion_z_axis(pose))
move_in_direction(back, 0.08)
