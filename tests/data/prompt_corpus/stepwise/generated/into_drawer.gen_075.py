# Task: put the peach into the second drawer; the drawer is closed, open it first.
# Plan:
# 1. The second drawer from the top is cabinet.drawer_1; its handle is cabinet.handle_1
#    (rows from the top: drawer_0 -> handle_0, drawer_1 -> handle_1, door_0 -> handle_2). Look at the scene.
# 2. Grasp the handle horizontally, close the gripper, attach the drawer.
# 3. Get the drawer's prismatic joint near the handle and pull along its axis, most of the way it can open
#    (at most 25 cm).
# 4. Release the handle and back away along the axis.
# 5. Grasp the peach from above at its middle, close, attach, lift.
# 6. Look again (the drawer moved), find a place pose inside the open drawer, move there.
# 7. Release the peach and move up.

# Step 1: look at the scene.
detect_objects()

# Step 2: grasp the second drawer's handle and attach the drawer.
open_gripper()
grasp(grasp_pose=parse_horizontal_grasp_pose(object_name='cabinet.handle_1'))
close_gripper()
attach_object(object_name='cabinet.drawer_1')

# Step 3: pull the drawer open along its joint axis.
handle_position = get_object_center_position(object_name='cabinet.handle_1')
joint = get_object_joint_info(object_name='cabinet', position=handle_position, type='prismatic')
pull = min(0.9 * (joint['joint_upper'] - joint['joint_value']), 0.25)
move_in_direction(axis=joint['joint_axis'], distance=pull)

# Step 4: release the handle and back away.
open_gripper()
detach_object(object_name='cabinet.drawer_1')
move_in_direction(axis=joint['joint_axis'], distance=0.05)

# Step 5: grasp the peach from above, lift it.
grasp(grasp_pose=parse_central_lift_grasp_pose(object_name='peach', description='center'))
close_gripper()
attach_object(object_name='peach')
move_in_direction(axis=[0, 0, 1], distance=0.1)

# Step 6: look again (the drawer is now open), then move to a place pose inside it.
detect_objects(object_list=[name for name in get_object_name_list() if name != 'peach'])
move_to_pose(pose=parse_place_pose(object_name='peach', receptacle_name='cabinet.drawer_1'))

# Step 7: release and move up.
open_gripper()
detach_object(object_name='peach')
move_in_direction(axis=[0, 0, 1], distance=0.08)
