# Task: put the tea box next to the white and pink box.
# Plan:
# 1. Detect everything; measure the boxes of the tea box and of the white and pink box.
# 2. Candidate spots touch-free beside the white and pink box: to its left (+y), right (-y), front (-x, towards
#    the robot) and back (+x), each 3 cm away from it counted from both boxes' half sizes. Try them nearest to the
#    tea box first, and take the first whose footprint is on the table and clear of every other object's box.
# 3. Grasp the tea box (top-down at its middle if narrow enough, else the adaptive grasp), attach it, lift it.
# 4. Place it at the chosen spot on the table, release it, move up.
detect_objects()
mover = 'tea_box'
anchor = 'white_and_pink_box'
gap = 0.03
mover_box = get_3d_bbox(mover)
anchor_box = get_3d_bbox(anchor)
half_x = (mover_box[3] - mover_box[0]) / 2.0
half_y = (mover_box[4] - mover_box[1]) / 2.0
anchor_c = get_object_center_position(anchor)
mover_c = get_object_center_position(mover)
table_box = get_3d_bbox('table')
table_top = table_box[5]


def spot_is_free(x, y, ignore):
    # The footprint around (x, y) must lie on the table and keep 2 cm from every other object's box.
    if x - half_x < table_box[0] + 0.02 or x + half_x > table_box[3] - 0.02:
        return False
    if y - half_y < table_box[1] + 0.02 or y + half_y > table_box[4] - 0.02:
        return False
    for other in get_object_name_list():
        if other == 'table' or other in ignore:
            continue
        b = get_3d_bbox(other)
        if x + half_x > b[0] - 0.02 and x - half_x < b[3] + 0.02 and y + half_y > b[1] - 0.02 and y - half_y < b[4] + 0.02:
            return False
    return True


candidates = [
    [anchor_c[0], anchor_box[4] + gap + half_y],
    [anchor_c[0], anchor_box[1] - gap - half_y],
    [anchor_box[0] - gap - half_x, anchor_c[1]],
    [anchor_box[3] + gap + half_x, anchor_c[1]],
]
candidates.sort(key=lambda c: (c[0] - mover_c[0]) ** 2 + (c[1] - mover_c[1]) ** 2)
spot = candidates[0]
for c in candidates:
    if spot_is_free(c[0], c[1], [mover, anchor]):
        spot = c
        break
target = [spot[0], spot[1], table_top]

open_gripper()
if min(2 * half_x, 2 * half_y) < 0.07:
    grasp_pose = parse_central_lift_grasp_pose(object_name=mover, description='center')
else:
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=mover, preferred_position=mover_c, preferred_approach_direction=[0, 0, -1])
grasp(grasp_pose)
close_gripper()
attach_object(mover)
lift = get_gripper_pose()
lift.position.z += 0.1
move_to_pose(lift)

move_to_pose(parse_place_pose(object_name=mover, position=target))
open_gripper()
detach_object(mover)
up = get_gripper_pose()
up.position.z += 0.1
move_to_pose(up)
