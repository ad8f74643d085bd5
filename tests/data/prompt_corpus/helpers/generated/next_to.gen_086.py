# Task: move the gelatin box next to the white bowl.
# Plan:
# 1. Detect everything; measure the boxes of the white bowl, the gelatin box and the table.
# 2. Candidate spots beside the bowl, one on each side: left (+y), right (-y), towards the robot (-x) and away
#    from it (+x), each leaving a 3 cm gap between the bowl's edge and the gelatin box's edge (the box's half size
#    taken as its larger horizontal half side, since it may turn in the hand).
# 3. Prefer spots that lie on the table with room for the box and at least 25 cm from the robot's base (x = -0.45,
#    y = 0); among them take the one with the most free room from every other object (room counted up to 15 cm),
#    then the one nearest the robot's base.
# 4. Pick the gelatin box from above, place it at the chosen spot on the table, release it and move up.

ROBOT_BASE_XY = np.array([-0.45, 0.0])
GAP = 0.03          # metres between the bowl's edge and the box's edge
ROOM_CAP = 0.15     # more free room than this counts the same
BASE_CLEARANCE = 0.25


def pick(name, lift=0.1):
    # Grasp `name` from above, attach it and lift it; a second try with the adaptive grasp if the first held nothing.
    for attempt in range(2):
        open_gripper()
        if attempt == 0:
            try:
                pose = parse_central_lift_grasp_pose(object_name=name, description='center')
            except GraspError:
                pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        else:
            pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        grasp(pose)
        close_gripper()
        try:
            attach_object(name)
        except GraspError:
            if attempt == 1:
                raise
            open_gripper()
            move_in_direction([0, 0, 1], 0.1)
            detect_objects([name])
            continue
        move_in_direction([0, 0, 1], lift)
        return


def place(name, receptacle=None, position=None):
    # Set the held `name` down in/on `receptacle` or at `position`, let go and move up.
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def footprint_distance(xy, box):
    # Horizontal distance from the point `xy` to the box `box` (0 inside it).
    dx = max(box[0] - xy[0], 0.0, xy[0] - box[3])
    dy = max(box[1] - xy[1], 0.0, xy[1] - box[4])
    return float(np.hypot(dx, dy))


def spot_beside(bowl_name, mover):
    # The best spot for `mover` next to `bowl_name`, as [x, y, z] on the table top.
    bowl = get_3d_bbox(bowl_name)
    table = get_3d_bbox('table')
    moving = get_3d_bbox(mover)
    half = max(moving[3] - moving[0], moving[4] - moving[1]) / 2.0
    centre = np.array([(bowl[0] + bowl[3]) / 2.0, (bowl[1] + bowl[4]) / 2.0])
    half_bowl = np.array([(bowl[3] - bowl[0]) / 2.0, (bowl[4] - bowl[1]) / 2.0])
    # Everything else that takes room: the things on the table and the cabinet as a whole (its parts lie in its box).
    others = [n for n in get_object_name_list()
              if n not in ('table', bowl_name, mover) and not n.startswith('cabinet.')]
    other_boxes = [get_3d_bbox(n) for n in others]

    best, best_key = None, None
    for direction in ([0.0, 1.0], [0.0, -1.0], [-1.0, 0.0], [1.0, 0.0]):
        d = np.array(direction)
        xy = centre + d * (float(np.dot(np.abs(d), half_bowl)) + GAP + half)
        on_table = (table[0] + half <= xy[0] <= table[3] - half) and (table[1] + half <= xy[1] <= table[4] - half)
        far_from_base = np.linalg.norm(xy - ROBOT_BASE_XY) >= BASE_CLEARANCE
        room = min([footprint_distance(xy, b) for b in other_boxes] + [ROOM_CAP])
        fits = room >= half
        key = (on_table and far_from_base, fits, room, -np.linalg.norm(xy - ROBOT_BASE_XY))
        if best_key is None or key > best_key:
            best, best_key = xy, key
    return [float(best[0]), float(best[1]), float(table[5])]


detect_objects()
target = spot_beside('white_bowl', 'gelatin_box')
pick('gelatin_box')
place('gelatin_box', position=target)
