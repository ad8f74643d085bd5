# Task: put the blue mug into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1; its handle is cabinet.handle_1
#    (rows from the top: drawer_0 -> handle_0, drawer_1 -> handle_1, door_0 -> handle_2).
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Get the drawer's prismatic joint near the handle and pull along its axis as far as it opens.
# 4. Release the handle, back away along the axis, and detect the drawer again now that it moved.
# 5. Grasp the blue mug from above with an adaptive grasp (by its rim or handle) and lift it.
# 6. Place the mug into the open drawer, release it and move up.
detect_objects()

# Open the second drawer
open_gripper()
grasp(parse_horizontal_grasp_pose('cabinet.handle_1'))
close_gripper()
attach_object('cabinet.drawer_1')
handle_position = get_object_center_position('cabinet.handle_1')
joint = get_object_joint_info('cabinet', handle_position, 'prismatic')
joint_axis = np.array(joint['joint_axis'])
open_distance = joint['joint_upper'] - joint['joint_value']
if open_distance < 0.15:
    open_distance = 0.15
move_in_direction(joint_axis, open_distance)
open_gripper()
detach_object('cabinet.drawer_1')
move_in_direction(joint_axis, 0.05)
detect_objects(['cabinet.drawer_1', 'blue_mug'])

# Pick the blue mug
open_gripper()
grasp(parse_adaptive_shape_grasp_pose('blue_mug', preferred_approach_direction=np.array([0, 0, -1])))
close_gripper()
attach_object('blue_mug')
move_in_direction(np.array([0, 0, 1]), 0.1)

# Place it into the open drawer
move_to_pose(parse_place_pose('blue_mug', 'cabinet.drawer_1'))
open_gripper()
detach_object('blue_mug')
move_in_direction(np.array([0, 0, 1]), 0.08)
