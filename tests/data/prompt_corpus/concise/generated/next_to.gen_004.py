# Task: put the red box next to the green plate.
# Plan:
# 1. Target: on the table just left (+y) of the plate, 3 cm beyond its edge, in line with its centre in x.
# 2. Grasp the red box from above, lift it.
# 3. Place it at the target, release it, move up.
detect_objects()
plate = get_3d_bbox('green_plate')
box = get_3d_bbox('red_box')
target = [(plate[0] + plate[3]) / 2, plate[4] + (box[4] - box[1]) / 2 + 0.03, plate[2]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='red_box', description='center'))
close_gripper()
attach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='red_box', position=target))
open_gripper()
detach_object('red_box')
move_in_direction([0, 0, 1], 0.1)
