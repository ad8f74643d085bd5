# Task: place the strawberry in the red bowl.
# Plan:
# 1. Detect the strawberry and the red bowl; the target is the middle of the bowl's box in x, y.
# 2. Grasp the strawberry top-down at its middle, attach it, lift it (a Pose from the gripper's) so that its
#    bottom clears the bowl's rim.
# 3. Place it in the bowl at the target, release it, move up.
detect_objects(object_list=['strawberry', 'red_bowl'])
bowl_box = get_3d_bbox('red_bowl')
target = [(bowl_box[0] + bowl_box[3]) / 2.0, (bowl_box[1] + bowl_box[4]) / 2.0, bowl_box[5]]

bottom_z = get_object_pose('strawberry').position.z
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='strawberry', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('strawberry')
hold = grasp_pose.position.z - bottom_z
lift = get_gripper_pose()
lift.position.z = max(lift.position.z + 0.1, bowl_box[5] + hold + 0.05)
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='strawberry', receptacle_name='red_bowl', position=target))
open_gripper()
detach_object('strawberry')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
