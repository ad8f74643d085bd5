# Task: open the second top cabinet drawer and place all boxes into it.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1. The boxes, from the names,
#    are white_and_pink_box and brown_box.
# 2. Measure the handle's centre, the outward normal of the drawer's front there (the hand approaches against it)
#    and the drawer's prismatic joint. Grasp the handle horizontally, attach the drawer, pull it along +axis by
#    most of what is left of its travel (joint_upper - joint_value), release it, back away along the normal.
# 3. Detect again (the drawer moved). The part of the drawer now out of the cabinet lies between the cabinet's
#    front and the drawer's new front: take its middle, and two spots side by side across the drawer's width
#    (a quarter of the width either side of the middle), one for each box.
# 4. For each box: grasp it (top-down at its middle if its box is narrower than the fingers open, else the
#    adaptive grasp), attach it, lift it (a Pose from the gripper's), place it into the drawer at its spot,
#    release it, move up.
detect_objects()
drawer = 'cabinet.drawer_1'
handle = 'cabinet.handle_1'
boxes = ['white_and_pink_box', 'brown_box']

handle_at = np.array(get_object_center_position(handle))
front_normal = np.array(get_plane_normal(drawer, handle_at))
joint = get_object_joint_info(object_name='cabinet', position=handle_at, type='prismatic')
axis = np.array(joint['joint_axis'])
travel = min(0.9 * (joint['joint_upper'] - joint['joint_value']), 0.3)

open_gripper()
grasp(parse_horizontal_grasp_pose(object_name=handle, approach_direction=(-front_normal).tolist()))
close_gripper()
attach_object(drawer)
move_in_direction(axis, travel)
open_gripper()
detach_object(drawer)
back = get_gripper_pose()
back.position.x += 0.08 * front_normal[0]
back.position.y += 0.08 * front_normal[1]
back.position.z += 0.08 * front_normal[2]
move_to_pose(back)

detect_objects()
drawer_box = get_3d_bbox(drawer)
inside = handle_at + axis * (travel / 2.0 - 0.04)
across = np.array([-axis[1], axis[0], 0.0])
across = across / np.linalg.norm(across)
width = abs(across[0]) * (drawer_box[3] - drawer_box[0]) + abs(across[1]) * (drawer_box[4] - drawer_box[1])
spots = [inside + across * width / 4.0, inside - across * width / 4.0]


def grasp_pose_for(name):
    box = get_3d_bbox(name)
    if min(box[3] - box[0], box[4] - box[1]) < 0.07:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_position=get_object_center_position(name), preferred_approach_direction=[0, 0, -1])


for name, spot in zip(boxes, spots):
    bottom_z = get_object_pose(name).position.z
    open_gripper()
    grasp_pose = grasp_pose_for(name)
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    hold = grasp_pose.position.z - bottom_z
    lift = get_gripper_pose()
    lift.position.z = max(lift.position.z + 0.1, drawer_box[5] + hold + 0.05)
    move_to_pose(lift)
    target = [spot[0], spot[1], drawer_box[5]]
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=drawer, position=target))
    open_gripper()
    detach_object(name)
    up = get_gripper_pose()
    up.position.z += 0.08
    move_to_pose(up)
