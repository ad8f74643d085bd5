# Task: sort the objects on the table by colour: put the green objects on the green plate.
# Plan:
# 1. From the names, the only green object (besides the plate itself) is green_apple; apple, tea_box, red_box and
#    red_bowl are not green and stay.
# 2. Detect; the target is the middle of the green plate's box in x, y.
# 3. Grasp the green apple top-down at its middle, attach it, lift it (a Pose from the gripper's).
# 4. Place it on the plate at the target, release it, move up.
detect_objects()
plate_box = get_3d_bbox('green_plate')
target = [(plate_box[0] + plate_box[3]) / 2.0, (plate_box[1] + plate_box[4]) / 2.0, plate_box[5]]

open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='green_apple', description='center'))
close_gripper()
attach_object('green_apple')
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name='green_apple', receptacle_name='green_plate', position=target))
open_gripper()
detach_object('green_apple')
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
