# Task: swing the cabinet door open
# Plan:
# 1. The door's handle is the one whose height lies within the door's box (the other is the drawer's).
# 2. Grasp that handle horizontally and attach the door.
# 3. Get the revolute joint near the handle and follow an arc about the hinge, in small steps.
# 4. Release the handle and move back out of the door's way.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


detect_objects()
door_box = get_3d_bbox('cabinet.door_0')
handle = [h for h in ['cabinet.handle_0', 'cabinet.handle_1'] if door_box[2] <= get_object_center_position(h)[2] <= door_box[5]][0]
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=60)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
back = -np.array(quaternion_z_axis(get_gripper_pose()))
move_in_direction(back, 0.08)
