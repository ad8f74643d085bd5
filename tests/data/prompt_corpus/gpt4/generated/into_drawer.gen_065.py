# Task: put the red cup into the top drawer; the drawer is closed, open it first
# Plan:
# 1. Detect the objects. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0.
# 2. Grasp the handle against the drawer front, close the gripper, attach the drawer.
# 3. Get the prismatic joint near the handle and pull along +joint_axis to open the drawer.
# 4. Release the handle, back away, and detect again since the drawer moved.
# 5. Grasp the red cup from above with the adaptive grasp, lift it.
# 6. Place the cup into the open top drawer, release it and move up.
detect_objects()

handle_pos = get_object_center_position('cabinet.handle_0')
joint = get_object_joint_info('cabinet', handle_pos, 'prismatic')
axis = np.array(joint['joint_axis'])

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('cabinet.handle_0', handle_pos, -axis))
close_gripper()
attach_object('cabinet.drawer_0')
pull = min(0.25, joint['joint_upper'] - joint['joint_value'])
move_in_direction(axis, pull)
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(axis, 0.05)

detect_objects()

open_gripper()
grasp(parse_adaptive_shape_grasp_pose('red_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('red_cup')
move_in_direction([0, 0, 1], 0.15)
move_to_pose(parse_place_pose('red_cup', 'cabinet.drawer_0'))
open_gripper()
detach_object('red_cup')
move_in_direction([0, 0, 1], 0.1)
