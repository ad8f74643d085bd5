# Task: open the top drawer of the cabinet and put the red box into it.
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0.
# 2. Read the drawer's prismatic joint near the handle: how far it is open and how far it opens at most.
# 3. Grasp the handle horizontally, attach the drawer, pull along +axis by the rest of its travel
#    (less 1 cm), release and back away along +axis with a Pose built from the gripper pose.
# 4. Detect again: the drawer has moved.
# 5. Grasp the red box from above (across its narrower side if it fits the gripper, else the adaptive
#    grasp from above), lift it so its bottom clears the top of the open drawer.
# 6. Place it into the drawer, release it and move straight up.
def shifted_pose(pose, direction, distance):
    # A copy of pose, moved by distance metres along direction, same orientation.
    d = np.array(direction, dtype=float)
    d = d / np.linalg.norm(d)
    new_pose = Pose()
    new_pose.position.x = pose.position.x + distance * d[0]
    new_pose.position.y = pose.position.y + distance * d[1]
    new_pose.position.z = pose.position.z + distance * d[2]
    new_pose.orientation.x = pose.orientation.x
    new_pose.orientation.y = pose.orientation.y
    new_pose.orientation.z = pose.orientation.z
    new_pose.orientation.w = pose.orientation.w
    return new_pose


detect_objects()

# Open the top drawer as far as it goes (less a small margin).
handle_position = get_object_center_position('cabinet.handle_0')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='prismatic')
axis = np.array(joint['joint_axis'], dtype=float)
pull = joint['joint_upper'] - joint['joint_value'] - 0.01
if pull > 0.005:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
    close_gripper()
    attach_object('cabinet.drawer_0')
    move_in_direction(axis, pull)
    open_gripper()
    detach_object('cabinet.drawer_0')
    move_to_pose(shifted_pose(get_gripper_pose(), axis, 0.06))

# The drawer moved: measure it anew.
detect_objects(object_list=['cabinet.drawer_0', 'red_box'])
drawer_box = get_3d_bbox('cabinet.drawer_0')
box_bbox = get_3d_bbox('red_box')

# Grasp the red box from above.
open_gripper()
narrow_side = min(box_bbox[3] - box_bbox[0], box_bbox[4] - box_bbox[1])
if narrow_side < 0.075:
    grasp(parse_central_lift_grasp_pose(object_name='red_box', description='center'))
else:
    grasp(parse_adaptive_shape_grasp_pose(object_name='red_box', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('red_box')

# Lift until the box's bottom is at least 5 cm above the drawer's top edge (and 10 cm at the least).
box_bottom = get_3d_bbox('red_box')[2]
lift = max(0.1, drawer_box[5] + 0.05 - box_bottom)
move_to_pose(shifted_pose(get_gripper_pose(), [0, 0, 1], lift))

# Into the open drawer.
move_to_pose(parse_place_pose(object_name='red_box', receptacle_name='cabinet.drawer_0'))
open_gripper()
detach_object('red_box')
move_to_pose(shifted_pose(get_gripper_pose(), [0, 0, 1], 0.1))
