# Task: place the green cup onto the blue plate.
# Plan:
# 1. Detect; read the boxes of the green cup and the blue plate.
# 2. Target: the plate's box centre in x, y, z at the plate's top; check that the cup's footprint is smaller
#    than the plate.
# 3. Grasp the cup with the adaptive grasp from above (by its rim or body), lift it clear of the plate.
# 4. Get a place pose at the target on the blue plate, move there, release, move up.
# 5. Detect again and check that the cup's centre lies over the plate.


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


detect_objects()
plate = get_3d_bbox('blue_plate')
cup = get_3d_bbox('green_cup')
target = box_centre(plate)
target[2] = plate[5]
cup_size = max(cup[3] - cup[0], cup[4] - cup[1])
plate_size = min(plate[3] - plate[0], plate[4] - plate[1])
print('plate centre', np.round(target, 3), 'plate', round(float(plate_size), 3), 'm, cup', round(float(cup_size), 3), 'm')
if cup_size > plate_size:
    print('warning: the cup is wider than the plate')

open_gripper()
grasp(parse_adaptive_shape_grasp_pose(object_name='green_cup', preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object('green_cup')
move_in_direction([0, 0, 1], max(0.1, plate[5] - cup[2]))
move_to_pose(parse_place_pose(object_name='green_cup', receptacle_name='blue_plate', position=list(target)))
open_gripper()
detach_object('green_cup')
move_in_direction([0, 0, 1], 0.1)

detect_objects()
plate = get_3d_bbox('blue_plate')
c = get_object_center_position('green_cup')
over = plate[0] <= c[0] <= plate[3] and plate[1] <= c[1] <= plate[4]
print('green cup now at', np.round(c, 3), 'over the plate:', over)
