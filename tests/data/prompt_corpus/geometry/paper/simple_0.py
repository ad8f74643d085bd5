# Task: place the apple into the footed bowl.
# Plan:
# 1. Detect the apple and the footed bowl; the target is the middle of the bowl's box in x, y.
# 2. Grasp the apple top-down at its middle, attach it, and lift it (a Pose from the gripper's) until its bottom
#    is 5 cm above the bowl's rim.
# 3. Place it in the bowl at the target, release it, move up.
detect_objects(object_list=['apple', 'footed_bowl'])
bowl_box = get_3d_bbox('footed_bowl')
target = [(bowl_box[0] + bowl_box[3]) / 2.0, (bowl_box[1] + bowl_box[4]) / 2.0, bowl_box[5]]

apple_bottom = get_object_pose('apple').position.z
open_gripper()
grasp_pose = parse_central_lift_grasp_pose(object_name='apple', description='center')
grasp(grasp_pose)
close_gripper()
attach_object('apple')
hold = grasp_pose.position.z - apple_bottom
lift = get_gripper_pose()
lift.position.z = max(lift.position.z + 0.1, bowl_box[5] + hold + 0.05)
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='apple', receptacle_name='footed_bowl', position=target))
open_gripper()
detach_object('apple')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
