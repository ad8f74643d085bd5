# Task: put the peach next to the green plate.
# Plan:
# 1. Detect everything. The object to move is peach, the reference green_plate (the plate stays put; "next to"
#    means beside it on the table, not on it; the can, the block and the cabinet are obstacles only).
# 2. Work out spots beside the plate, to its left, right, front and back: the peach's centre a 3 cm gap beyond the
#    plate's box edge. Keep only spots on the table whose footprint (the peach's larger half-width around the spot)
#    overlaps no other object's box, and try the nearest to the peach first.
# 3. Pick the peach: a central lift grasp from above, at mid height; if that fails, or the cameras do
#    not see the peach rise with the hand, let go and retry once with the adaptive grasp.
# 4. Ask parse_place_pose for the spot (it moves to the nearest free spot if needed), move there, release, move up;
#    if no pose can be found for a spot, try the next one while still holding the peach.
# 5. Check with a fresh detection: the peach rests on the table, its centre is outside the plate's box and the gap
#    between their boxes is at most 8 cm. If not, pick it again and try the next spot.


def approach_axis(pose):
    # The gripper's approach (z) axis, from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance=0.1):
    # Move the hand straight back along its approach axis.
    move_in_direction(-approach_axis(get_gripper_pose()), distance)


def grasp_options(name):
    # The grasp tool to try first and a different one to retry with.
    return [
        ('central lift grasp', lambda: parse_central_lift_grasp_pose(object_name=name, description='center')),
        ('adaptive grasp', lambda: parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])),
    ]


def pick(name):
    # Grasp, attach and lift the object; it counts as picked only if the cameras see it rise with the hand.
    for label, make_grasp in grasp_options(name):
        detect_objects([name])
        z_before = get_object_center_position(name)[2]
        open_gripper()
        reached = False
        try:
            grasp(make_grasp())
            reached = True
            close_gripper()
            attach_object(name)
        except Exception as error:  # GraspError, IKError or PlanningError
            print('[pick] ' + label + ' of ' + name + ' failed: ' + str(error))
            open_gripper()
            if reached:
                back_off(0.1)
            continue
        move_in_direction([0, 0, 1], 0.1)
        detect_objects([name])
        if get_object_center_position(name)[2] > z_before + 0.05:
            return label
        print('[pick] ' + name + ' did not rise with the hand after the ' + label + '; letting go')
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], 0.05)
    raise RuntimeError('could not pick up ' + name + ' with either grasp tool')


def place(name, receptacle=None, position=None):
    # Set the held object down where parse_place_pose says, let go and move up.
    if position is None:
        pose = parse_place_pose(object_name=name, receptacle_name=receptacle)
    else:
        pose = parse_place_pose(object_name=name, position=[float(v) for v in position])
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def xy_gap(a, b):
    # Horizontal clearance between two boxes [x_min, y_min, z_min, x_max, y_max, z_max]; 0 where they overlap.
    dx = max(0.0, a[0] - b[3], b[0] - a[3])
    dy = max(0.0, a[1] - b[4], b[1] - a[4])
    return float(np.hypot(dx, dy))


def spots_next_to(name, anchor, gap=0.03):
    # Spots beside the anchor on its four sides, free ones only, nearest to the object first.
    detect_objects()
    table = get_3d_bbox('table')
    anchor_box = get_3d_bbox(anchor)
    own = get_3d_bbox(name)
    half = max(own[3] - own[0], own[4] - own[1]) / 2
    cx, cy = (anchor_box[0] + anchor_box[3]) / 2, (anchor_box[1] + anchor_box[4]) / 2
    here = get_object_center_position(name)
    others = [n for n in get_object_name_list() if n not in ('table', name, anchor)]
    every, free = [], []
    for dx, dy in [(0, 1), (0, -1), (-1, 0), (1, 0)]:  # left, right, towards the robot, away from it
        reach = (anchor_box[3] - anchor_box[0]) / 2 if dx else (anchor_box[4] - anchor_box[1]) / 2
        x = cx + dx * (reach + half + gap)
        y = cy + dy * (reach + half + gap)
        spot = [x, y, table[5]]
        every.append(spot)
        footprint = [x - half, y - half, 0.0, x + half, y + half, 0.0]
        on_table = table[0] <= footprint[0] and footprint[3] <= table[3] and table[1] <= footprint[1] and footprint[4] <= table[4]
        if on_table and all(xy_gap(footprint, get_3d_bbox(other)) > 0.0 for other in others):
            free.append(spot)
    spots = free if free else every
    spots.sort(key=lambda p: float(np.hypot(p[0] - here[0], p[1] - here[1])))
    return spots


def is_next_to(name, anchor):
    # Fresh look: on the table, not on or in the anchor, and within 8 cm of it.
    detect_objects([name, anchor])
    own = get_3d_bbox(name)
    anchor_box = get_3d_bbox(anchor)
    centre = get_object_center_position(name)
    on_table = abs(own[2] - get_3d_bbox('table')[5]) < 0.02
    outside = not (anchor_box[0] <= centre[0] <= anchor_box[3] and anchor_box[1] <= centre[1] <= anchor_box[4])
    return bool(on_table and outside and xy_gap(own, anchor_box) <= 0.08)


def put_next_to(name, anchor):
    holding = False
    for spot in spots_next_to(name, anchor):
        if not holding:
            pick(name)
            holding = True
        try:
            place(name, position=spot)
        except Exception as error:  # PlacementError, IKError or PlanningError: still holding it
            print('[place] spot ' + str([round(float(v), 3) for v in spot]) + ' failed: ' + str(error))
            continue
        holding = False
        if is_next_to(name, anchor):
            return
        print('[check] ' + name + ' did not end up next to ' + anchor + '; trying another spot')
    if holding:
        place(name, receptacle='table')
    raise RuntimeError(name + ' could not be put next to ' + anchor)


detect_objects()
put_next_to('peach', 'green_plate')
