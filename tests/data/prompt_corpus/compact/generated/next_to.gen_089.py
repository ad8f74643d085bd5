# Task: put the peach next to the green plate
# Plan:
# 1. Measure the plate and the peach; the target is beside the plate along y, on the side where the peach already is,
#    offset by half the plate's width + half the peach's width + a 3 cm gap, on the table (not on the plate).
# 2. Grasp the peach from above at its middle, lift it.
# 3. Place it at the target, release it, move up.
detect_objects()
plate_box = get_3d_bbox('green_plate')
peach_box = get_3d_bbox('peach')
plate_at = get_object_center_position('green_plate')
peach_at = get_object_center_position('peach')
side = 1.0 if peach_at[1] >= plate_at[1] else -1.0
offset = (plate_box[4] - plate_box[1]) / 2 + (peach_box[4] - peach_box[1]) / 2 + 0.03
target = [plate_at[0], plate_at[1] + side * offset, get_3d_bbox('table')[5]]
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='peach', description='center'))
close_gripper()
attach_object('peach')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='peach', position=target))
open_gripper()
detach_object('peach')
move_in_direction([0, 0, 1], 0.1)
