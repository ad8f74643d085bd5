# Task: put the blue block into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1, its handle cabinet.handle_1. Measure the handle's
#    centre, the outward normal of the drawer's front there (the hand approaches against it) and the drawer's
#    prismatic joint.
# 2. Grasp the handle horizontally, attach the drawer, pull it along +axis by most of what is left of its travel
#    (joint_upper - joint_value), release it and back away along the front's normal.
# 3. Detect again (the drawer moved). Aim at the middle of the part of the drawer now out of the cabinet.
# 4. Grasp the block top-down at its middle, attach it, lift it.
# 5. Place it into the drawer at that spot, release it, move up.
detect_objects()
handle_at = np.array(get_object_center_position('cabinet.handle_1'))
front_normal = np.array(get_plane_normal('cabinet.drawer_1', handle_at))
joint = get_object_joint_info(object_name='cabinet', position=handle_at, type='prismatic')
axis = np.array(joint['joint_axis'])
travel = min(0.9 * (joint['joint_upper'] - joint['joint_value']), 0.3)

open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_1', approach_direction=(-front_normal).tolist()))
close_gripper()
attach_object('cabinet.drawer_1')
move_in_direction(axis, travel)
open_gripper()
detach_object('cabinet.drawer_1')
back = get_gripper_pose()
back.position.x += 0.08 * front_normal[0]
back.position.y += 0.08 * front_normal[1]
back.position.z += 0.08 * front_normal[2]
move_to_pose(back)

detect_objects()
drawer_box = get_3d_bbox('cabinet.drawer_1')
# The drawer's front moved out by `travel`; the handle sits about 4 cm in front of its inside.
inside = handle_at + axis * (travel / 2.0 - 0.04)
target = [inside[0], inside[1], drawer_box[5]]

block_bottom = get_object_pose('blue_block').position.z
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='blue_block', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('blue_block')
hold = grasp_pose.position.z - block_bottom
lift = get_gripper_pose()
lift.position.z = max(lift.position.z + 0.1, drawer_box[5] + hold + 0.05)
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='blue_block', receptacle_name='cabinet.drawer_1', position=target))
open_gripper()
detach_object('blue_block')
up = get_gripper_pose()
up.position.z += 0.08
move_to_pose(up)
