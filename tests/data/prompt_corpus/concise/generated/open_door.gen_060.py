# Task: open the cabinet door.
# Plan:
# 1. The door is cabinet.door_0; its handle is cabinet.handle_2 (third row, below the two drawers).
# 2. Grasp the handle horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint near the handle and follow an arc about the hinge.
# 4. Release the handle and back away along the gripper's approach axis.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_2'))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_2'), type='revolute')
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=60)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
back = -np.array(quaternion_z_axis(get_gripper_pose()))
move_in_direction(back, 0.08)
