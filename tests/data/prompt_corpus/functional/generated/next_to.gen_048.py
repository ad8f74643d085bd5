# Task: place the white mug beside the white bowl.
# Plan:
# 1. Detect the scene; measure the bowl, the mug, the table and the other things on the table.
# 2. Two candidate spots beside the bowl, left (+y) and right (-y): the bowl's side plus a small gap plus
#    the mug's half size, level with the bowl's centre in x.
# 3. Keep the candidates that lie on the table and not too near the robot's base; of those choose the one
#    farthest from every other object (clearance in x, y from their boxes).
# 4. Pick the mug with a grasp from above (its rim if it is wide), lift it.
# 5. Place it at the chosen spot on the table, release, move up.

MUG = 'white_mug'
BOWL = 'white_bowl'
GAP = 0.03
ROBOT_BASE_XY = np.array([-0.45, 0.0])
BASE_KEEPOUT = 0.2


def is_furniture(name):
    return name == 'table' or name == 'cabinet' or name.startswith('cabinet.')


def obstacles(exclude):
    return [name for name in get_object_name_list() if not is_furniture(name) and name not in exclude]


def half_footprint(box):
    # Half of the larger horizontal extent: the mug fits in this radius whatever its turn.
    return max(box[3] - box[0], box[4] - box[1]) / 2.0


def xy_distance_to_box(point, box):
    dx = max(box[0] - point[0], 0.0, point[0] - box[3])
    dy = max(box[1] - point[1], 0.0, point[1] - box[4])
    return float(np.hypot(dx, dy))


def on_table(point, half, table_box):
    return (table_box[0] + half <= point[0] <= table_box[3] - half
            and table_box[1] + half <= point[1] <= table_box[4] - half)


def clear_of_base(point, half):
    return np.linalg.norm(np.array(point[:2]) - ROBOT_BASE_XY) >= BASE_KEEPOUT + half


def candidate_spots(bowl_box, half):
    centre_x = (bowl_box[0] + bowl_box[3]) / 2.0
    left = [centre_x, bowl_box[4] + GAP + half]
    right = [centre_x, bowl_box[1] - GAP - half]
    return [left, right]


def clearance(point, half, obstacle_boxes):
    if not obstacle_boxes:
        return float('inf')
    return min(xy_distance_to_box(point, box) for box in obstacle_boxes) - half


def best_spot(bowl_box, half, table_box, obstacle_boxes):
    spots = [p for p in candidate_spots(bowl_box, half) if on_table(p, half, table_box) and clear_of_base(p, half)]
    if not spots:
        spots = candidate_spots(bowl_box, half)
    return max(spots, key=lambda p: clearance(p, half, obstacle_boxes))


def pick_from_above(name, lift=0.1):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place(name, pose, retreat=0.1):
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


def main():
    detect_objects()
    table_box = get_3d_bbox('table')
    bowl_box = get_3d_bbox(BOWL)
    half = half_footprint(get_3d_bbox(MUG))
    obstacle_boxes = [get_3d_bbox(name) for name in obstacles(exclude=[MUG, BOWL])]
    spot = best_spot(bowl_box, half, table_box, obstacle_boxes)
    target = [spot[0], spot[1], table_box[5]]
    pick_from_above(MUG)
    place(MUG, parse_place_pose(object_name=MUG, position=target))


main()
