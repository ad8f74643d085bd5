# Task: open the cabinet door and put the blue block in the cupboard behind it
# Plan:
# 1. The cabinet has a door and a drawer; which handle row is the door's is not given, so take the handle
#    whose height is nearest the middle of the door.
# 2. Grasp that handle horizontally, attach the door, swing it open 60 degrees about its hinge, release it and
#    back away.
# 3. Look again, grasp the blue block horizontally (it must be carried in level), lift it.
# 4. Place it into the compartment behind the open door, release it and back out the way the hand came.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


detect_objects()
door_box = get_3d_bbox('cabinet.door_0')
door_middle_z = (door_box[2] + door_box[5]) / 2
handle = min(['cabinet.handle_0', 'cabinet.handle_1'], key=lambda h: abs(get_object_center_position(h)[2] - door_middle_z))
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='revolute')
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=60)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
move_in_direction(-np.array(quaternion_z_axis(get_gripper_pose())), 0.08)
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='blue_block'))
close_gripper()
attach_object('blue_block')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='cabinet.door_0'))
open_gripper()
detach_object('blue_block')
move_in_direction(-np.array(quaternion_z_axis(get_gripper_pose())), 0.1)
