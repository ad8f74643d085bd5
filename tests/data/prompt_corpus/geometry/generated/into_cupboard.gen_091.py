# Task: put the yellow box into the cabinet behind its door; the door is closed, open it first
# Plan:
# 1. Detect everything. The door is cabinet.door_0; find its handle by geometry: the handle whose centre lies
#    within the door's height range (nearest its middle), not the drawer's handle.
# 2. Grasp that handle horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint near the handle; open it to 90 degrees (or its upper limit if less) by
#    following an arc about the hinge from the present gripper pose, in small steps.
# 4. Release the handle, back away along the hand's approach axis, detect again (the door moved).
# 5. Grasp the yellow_box with a horizontal grasp (needed to carry it in level), lift it.
# 6. Place it into the compartment behind the open door, release it, back out along the approach axis.
def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def find_door_handle():
    door_box = get_3d_bbox('cabinet.door_0')
    door_mid_z = (door_box[2] + door_box[5]) / 2
    handles = [name for name in get_object_name_list() if name.startswith('cabinet.handle_')]

    def score(name):
        z = get_object_center_position(name)[2]
        outside = max(door_box[2] - z, 0.0, z - door_box[5])
        return (outside, abs(z - door_mid_z))

    return min(handles, key=score)


detect_objects()
handle = find_door_handle()
handle_position = get_object_center_position(handle)

# Open the door.
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle))
close_gripper()
attach_object('cabinet.door_0')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='revolute')
target_angle = min(float(joint['joint_upper']), 90.0)
angle = target_angle - float(joint['joint_value'])
if angle > 0:
    n_steps = max(int(angle / 3), 5)
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'], joint_position=joint['joint_position'], n=n_steps, angle=angle)
    follow_path(path)
open_gripper()
detach_object('cabinet.door_0')
back = -quaternion_z_axis(get_gripper_pose())
move_in_direction(back, 0.1)
detect_objects()

# Pick the yellow_box level, so that it can be carried into the compartment.
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='yellow_box'))
close_gripper()
attach_object('yellow_box')
move_in_direction([0, 0, 1], 0.1)

# Put it behind the open door.
move_to_pose(parse_place_pose(object_name='yellow_box', receptacle_name='cabinet.door_0'))
open_gripper()
detach_object('yellow_box')
back = -quaternion_z_axis(get_gripper_pose())
move_in_direction(back, 0.05)
