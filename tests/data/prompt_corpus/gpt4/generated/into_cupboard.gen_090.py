# Task: open the cabinet door and put the rubiks cube in the cupboard behind it.
# Plan:
# 1. The query lists the door before the drawer, so the door is the top row: cabinet.door_0, its handle cabinet.handle_0.
# 2. Grasp the door's handle horizontally, attach the door, swing it open about its hinge
#    (70 degrees, well past the 40 needed to put things behind it), release and back away.
# 3. Look again, now that the door has moved.
# 4. Grasp the rubiks cube with a horizontal grasp (it must be carried in level), lift it.
# 5. Place it into the compartment behind the door, release it, back out.
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
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=20, angle=70)
follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
back = -np.array(quaternion_z_axis(get_gripper_pose()))
move_in_direction(back, 0.08)
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='rubiks_cube'))
close_gripper()
attach_object('rubiks_cube')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='rubiks_cube', receptacle_name='cabinet.door_0'))
open_gripper()
detach_object('rubiks_cube')
back = -np.array(quaternion_z_axis(get_gripper_pose()))
move_in_direction(back, 0.05)
