# Task: move the banana next to the blue bowl.
# Plan:
# 1. Look at the scene; measure the blue bowl, the banana and the table top.
# 2. Work out four candidate spots next to the bowl (towards the robot, away from it, left, right), each
#    leaving a 4 cm gap between the bowl's edge and the banana's box.
# 3. Keep the spots whose footprint lies on the table and stays at least 3 cm from every other thing;
#    of those take the one nearest the banana's present place (shortest move). If none is clear, take the
#    spot with the most room; the place pose shifts it to a free spot nearby.
# 4. Grasp the banana with the adaptive grasp from above (it is long and curved, so the centre of its box
#    may not lie on it), close, attach, lift.
# 5. Look again, place the banana at the chosen spot, release, move up.

MOVED = 'banana'
REFERENCE = 'blue_bowl'
GAP = 0.04
CLEARANCE = 0.03


def footprint_gap(spot, half_x, half_y, box):
    # Horizontal distance between the footprint centred at spot and an object's box (0 where they overlap).
    dx = max(0.0, box[0] - (spot[0] + half_x), (spot[0] - half_x) - box[3])
    dy = max(0.0, box[1] - (spot[1] + half_y), (spot[1] - half_y) - box[4])
    return float(np.hypot(dx, dy))


# Step 1: look at the scene and measure.
detect_objects()
reference_box = get_3d_bbox(object_name=REFERENCE)
reference_center = get_object_center_position(object_name=REFERENCE)
moved_box = get_3d_bbox(object_name=MOVED)
moved_center = get_object_center_position(object_name=MOVED)
table_box = get_3d_bbox(object_name='table')
half_x = (moved_box[3] - moved_box[0]) / 2
half_y = (moved_box[4] - moved_box[1]) / 2

# Step 2: candidate spots next to the bowl.
candidates = [
    [reference_box[0] - GAP - half_x, reference_center[1]],  # towards the robot (-x)
    [reference_box[3] + GAP + half_x, reference_center[1]],  # away from the robot (+x)
    [reference_center[0], reference_box[4] + GAP + half_y],  # left (+y)
    [reference_center[0], reference_box[1] - GAP - half_y],  # right (-y)
]

# Step 3: choose a spot on the table, clear of the other things, nearest the banana.
obstacles = [name for name in get_object_name_list()
             if name not in ('table', MOVED, REFERENCE) and not name.startswith('cabinet.')]
obstacle_boxes = [get_3d_bbox(object_name=name) for name in obstacles]


def on_table(spot):
    margin = 0.02
    return (table_box[0] + margin <= spot[0] - half_x and spot[0] + half_x <= table_box[3] - margin
            and table_box[1] + margin <= spot[1] - half_y and spot[1] + half_y <= table_box[4] - margin)


def room(spot):
    if not obstacle_boxes:
        return 1.0
    return min(footprint_gap(spot, half_x, half_y, box) for box in obstacle_boxes)


clear = [spot for spot in candidates if on_table(spot) and room(spot) >= CLEARANCE]
if clear:
    spot = min(clear, key=lambda s: np.hypot(s[0] - moved_center[0], s[1] - moved_center[1]))
else:
    on_top = [s for s in candidates if on_table(s)] or candidates
    spot = max(on_top, key=room)
target = [spot[0], spot[1], table_box[5]]

# Step 4: grasp the banana from above with the adaptive grasp, lift it.
open_gripper()
grasp(grasp_pose=parse_adaptive_shape_grasp_pose(object_name=MOVED, preferred_approach_direction=[0, 0, -1]))
close_gripper()
attach_object(object_name=MOVED)
move_in_direction(axis=[0, 0, 1], distance=0.1)

# Step 5: look again, place the banana next to the bowl, release, move up.
detect_objects(object_list=[name for name in get_object_name_list() if name != MOVED])
move_to_pose(pose=parse_place_pose(object_name=MOVED, position=target))
open_gripper()
detach_object(object_name=MOVED)
move_in_direction(axis=[0, 0, 1], distance=0.1)
