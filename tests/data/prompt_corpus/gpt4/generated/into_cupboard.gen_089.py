# Task: open the cabinet door and put the peach in the cupboard behind it
# Plan:
# 1. Detect all objects. The cabinet has one door (cabinet.door_0) and one drawer (cabinet.drawer_0); handles are
#    numbered from the top down, so whether the door's handle is cabinet.handle_0 or cabinet.handle_1 depends on
#    which part is on top. Pick the handle whose height lies within the door's box.
# 2. Grasp the door's handle horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint near the handle and follow an arc about the hinge to swing it about 60 degrees open
#    (at least 40 degrees is needed to place things behind it), no further than the joint allows.
# 4. Release the handle, detach the door, back the hand out along its approach axis.
# 5. Detect again, since the door moved.
# 6. Grasp the peach with a horizontal grasp (needed to carry it in level), close, attach, lift it a little.
# 7. Get a place pose in the compartment behind the open door, move there, open the gripper, detach the peach
#    (the hand backs out the way it came).
detect_objects()

# Step 1: find the door's handle.
door_box = get_3d_bbox('cabinet.door_0')
door_mid_z = (door_box[2] + door_box[5]) / 2
door_handle = None
best_score = None
for handle in ['cabinet.handle_0', 'cabinet.handle_1']:
    handle_z = get_object_center_position(handle)[2]
    outside = max(door_box[2] - handle_z, 0.0, handle_z - door_box[5])
    score = (outside, abs(handle_z - door_mid_z))
    if best_score is None or score < best_score:
        best_score = score
        door_handle = handle

# Step 2: grasp the door's handle and attach the door.
open_gripper()
handle_grasp_pose = parse_horizontal_grasp_pose(door_handle)
grasp(handle_grasp_pose)
close_gripper()
attach_object('cabinet.door_0')

# Step 3: swing the door open about its hinge.
handle_position = get_object_center_position(door_handle)
joint = get_object_joint_info('cabinet', handle_position, 'revolute')
open_angle = min(60.0, joint['joint_upper'] - joint['joint_value'])
path = generate_arc_path_around_joint(get_gripper_pose(), np.array(joint['joint_axis']), np.array(joint['joint_position']), 20, open_angle)
follow_path(path)

# Step 4: release the handle and back away along the gripper's approach (z) axis.
open_gripper()
detach_object('cabinet.door_0')
q = get_gripper_pose().orientation
approach = np.array([2 * (q.x * q.z + q.w * q.y), 2 * (q.y * q.z - q.w * q.x), 1 - 2 * (q.x * q.x + q.y * q.y)])
move_in_direction(-approach, 0.08)

# Step 5: look again now that the door is open.
detect_objects()

# Step 6: grasp the peach level and lift it.
open_gripper()
peach_grasp_pose = parse_horizontal_grasp_pose('peach')
grasp(peach_grasp_pose)
close_gripper()
attach_object('peach')
move_in_direction(np.array([0, 0, 1]), 0.05)

# Step 7: carry it into the compartment behind the door and let go.
place_pose = parse_place_pose('peach', 'cabinet.door_0')
move_to_pose(place_pose)
open_gripper()
detach_object('peach')
