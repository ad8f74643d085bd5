# Task: swing the cabinet door open.
# Plan:
# 1. Look at the scene. The cabinet has one door and one drawer and two handles; the query lists the door
#    first, so the door is probably the top row (cabinet.handle_0). To be sure, take the handle whose centre
#    lies nearest the door's box.
# 2. Grasp that handle horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint near the handle; work out how far it can still open (up to 90 degrees).
# 4. Follow an arc about the hinge from the present gripper pose, in small steps.
# 5. Release the handle and back the hand straight out along its approach axis, then move up.


def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]


def distance_to_box(point, box):
    # Distance from a point to an axis-aligned box (0 inside).
    lower = np.array(box[:3])
    upper = np.array(box[3:])
    outside = np.maximum(np.maximum(lower - point, point - upper), 0.0)
    return float(np.linalg.norm(outside))


# Step 1: look at the scene and find the door's handle.
detect_objects()
door_box = get_3d_bbox(object_name='cabinet.door_0')
handles = [name for name in get_object_name_list() if name.startswith('cabinet.handle_')]
door_handle = min(handles, key=lambda h: distance_to_box(get_object_center_position(object_name=h), door_box))

# Step 2: grasp the handle and attach the door.
open_gripper()
grasp(grasp_pose=parse_horizontal_grasp_pose(object_name=door_handle))
close_gripper()
attach_object(object_name='cabinet.door_0')

# Step 3: the door's hinge and how far to turn it.
handle_position = get_object_center_position(object_name=door_handle)
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='revolute')
angle = min(joint['joint_upper'], 90.0) - joint['joint_value']

# Step 4: swing the door open along an arc about the hinge.
path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                      joint_position=joint['joint_position'], n=30, angle=angle)
follow_path(path=path)

# Step 5: release, back out along the approach axis, move up.
open_gripper()
detach_object(object_name='cabinet.door_0')
back = -np.array(quaternion_z_axis(get_gripper_pose()))
move_in_direction(axis=back, distance=0.1)
move_in_direction(axis=[0, 0, 1], distance=0.05)
