# Task: put the peach into the top drawer; the drawer is closed, open it first.
# Plan:
# 1. The top drawer is cabinet.drawer_0, its handle cabinet.handle_0: open it by its handle first.
# 2. Look again, now that the drawer has moved.
# 3. Pick the peach from above.
# 4. Place it into the open drawer and release it.
detect_objects()
open_gripper()
grasp(parse_horizontal_grasp_pose(object_name='cabinet.handle_0'))
close_gripper()
attach_object('cabinet.drawer_0')
joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position('cabinet.handle_0'), type='prismatic')
move_in_direction(joint['joint_axis'], 0.22)
open_gripper()
detach_object('cabinet.drawer_0')
move_in_direction(joint['joint_axis'], 0.05)
detect_objects()
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='peach', description='center'))
close_gripper()
attach_object('peach')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='peach', receptacle_name='cabinet.drawer_0'))
open_gripper()
detach_object('peach')
move_in_direction([0, 0, 1], 0.08)
