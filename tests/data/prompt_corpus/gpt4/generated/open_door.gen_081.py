# Task: open the cabinet door wide.
# Plan:
# 1. The cabinet has one door (cabinet.door_0) and one drawer (cabinet.drawer_0); the handles are numbered
#    by row from the top, so find the door's handle as the handle whose height lies within the door's box.
# 2. Grasp that handle horizontally, close the gripper, attach the door.
# 3. Get the door's revolute joint (hinge) near the handle.
# 4. Turn the gripper about the hinge along an arc as far as the door opens (joint_upper), in small steps.
# 5. Release the handle and back out along the gripper's approach axis.
def find_handle_of(part_name):
    part_bbox = get_3d_bbox(part_name)
    part_center = get_object_center_position(part_name)
    handles = [name for name in get_object_name_list() if name.startswith('cabinet.handle_')]
    best_handle = None
    best_score = None
    for handle in handles:
        handle_center = get_object_center_position(handle)
        inside = part_bbox[2] - 0.01 <= handle_center[2] <= part_bbox[5] + 0.01
        score = np.linalg.norm(handle_center - part_center) - (10.0 if inside else 0.0)
        if best_score is None or score < best_score:
            best_score = score
            best_handle = handle
    return best_handle


def quaternion_z_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


detect_objects()
door_handle = find_handle_of('cabinet.door_0')

open_gripper()
grasp(parse_horizontal_grasp_pose(door_handle))
close_gripper()
attach_object('cabinet.door_0')

handle_position = get_object_center_position(door_handle)
joint = get_object_joint_info('cabinet', handle_position, 'revolute')
open_angle = joint['joint_upper'] - joint['joint_value']
if open_angle < 10.0:
    open_angle = 10.0
n_steps = int(open_angle / 3.0) + 1
path = generate_arc_path_around_joint(get_gripper_pose(), np.array(joint['joint_axis']), np.array(joint['joint_position']), n_steps, open_angle)
follow_path(path)

open_gripper()
detach_object('cabinet.door_0')
back = -quaternion_z_axis(get_gripper_pose())
move_in_direction(back, 0.08)
