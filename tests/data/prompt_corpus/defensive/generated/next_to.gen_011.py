# Task: put the blue mug next to the red mug.
# Plan:
# 1. Look at the scene; work out spots on the table just beside the red mug (left, right, nearer, farther),
#    from the sizes of the two mugs' boxes, 3 cm apart.
# 2. Pick the blue mug by its rim from above (adaptive grasp); if a grasp tool raises or the fingers close on
#    nothing, look again and fall back to the top-down grasp, then to a horizontal one. Lift it.
# 3. Place it at the first spot that parse_place_pose / move_to_pose accept, let go, move up.
# 4. Look again and check that the blue mug stands on the table within 8 cm of the red mug; if not, pick it
#    again and try the other spots, once.


def approach_axis(pose):
    # The gripper's approach (z) axis from its quaternion.
    x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
    return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])


def back_off(distance):
    # Moves the hand straight back along its approach axis (after a failed grasp or after letting go).
    try:
        move_in_direction(-approach_axis(get_gripper_pose()), distance)
    except Exception as error:
        print('could not back off:', error)


def top_grasp(name):
    return parse_central_lift_grasp_pose(object_name=name, description='center')


def rim_grasp(name):
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def side_grasp(name):
    return parse_horizontal_grasp_pose(object_name=name)


def pick(name, grasp_tools, lift=0.1):
    # Tries the grasp tools in order, looking again before each try, and falls back to the next tool when one
    # raises or the fingers close on nothing; two rounds at most. True when the object is held and lifted.
    for attempt in range(2):
        for make_grasp in grasp_tools:
            detect_objects(object_list=[name])
            open_gripper()
            try:
                grasp_pose = make_grasp(name)
            except Exception as error:
                print('no', make_grasp.__name__, 'for', name, ':', error)
                continue
            reached = False
            try:
                grasp(grasp_pose)
                reached = True
                close_gripper()
                attach_object(name)
            except Exception as error:
                print(make_grasp.__name__, 'of', name, 'failed:', error)
                open_gripper()
                if reached:
                    back_off(0.1)
                continue
            try:
                move_in_direction([0, 0, 1], lift)
            except Exception as error:
                print('could not lift', name, ':', error)
            return True
    return False


def set_down_on_table(name):
    # Frees the hand: sets the held object down on a free spot of the table.
    try:
        move_to_pose(parse_place_pose(object_name=name, receptacle_name='table'))
    except Exception as error:
        print('could not set', name, 'down on the table:', error)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def place(name, receptacle=None, position=None):
    # Moves the held object to its place and lets go; if that raises, looks again and tries once more, else sets
    # the object down on the table. True when it was let go at its place.
    for attempt in range(2):
        try:
            place_pose = parse_place_pose(object_name=name, receptacle_name=receptacle, position=position)
            move_to_pose(place_pose)
        except Exception as error:
            print('placing', name, 'failed:', error)
            detect_objects()
            continue
        open_gripper()
        detach_object(name)
        move_in_direction([0, 0, 1], 0.1)
        return True
    set_down_on_table(name)
    return False


def spots_beside(anchor, name, gap=0.03):
    # Spots on the table beside the anchor, the two boxes `gap` apart: to its left (+y), right (-y),
    # nearer the robot (-x), farther away (+x).
    a = get_3d_bbox(anchor)
    o = get_3d_bbox(name)
    centre = get_object_center_position(anchor)
    dx = (a[3] - a[0]) / 2 + (o[3] - o[0]) / 2 + gap
    dy = (a[4] - a[1]) / 2 + (o[4] - o[1]) / 2 + gap
    z = get_3d_bbox('table')[5]
    return [[centre[0], centre[1] + dy, z], [centre[0], centre[1] - dy, z],
            [centre[0] - dx, centre[1], z], [centre[0] + dx, centre[1], z]]


def is_next_to(name, anchor, max_gap=0.08):
    # True when the object stands on the table and its box is within max_gap of the anchor's box.
    a = get_3d_bbox(anchor)
    o = get_3d_bbox(name)
    gap_x = max(0.0, a[0] - o[3], o[0] - a[3])
    gap_y = max(0.0, a[1] - o[4], o[1] - a[4])
    on_table = o[2] <= get_3d_bbox('table')[5] + 0.03
    return on_table and max(gap_x, gap_y) <= max_gap


def place_beside(name, anchor, grasp_tools):
    # Picks the object and sets it down on the first spot beside the anchor that works; looks again, checks that
    # it stands next to the anchor, and if not tries once more with the other spots.
    spots = spots_beside(anchor, name)
    for attempt in range(2):
        if not pick(name, grasp_tools):
            return False
        used = None
        for i, spot in enumerate(spots):
            try:
                move_to_pose(parse_place_pose(object_name=name, position=spot))
            except Exception as error:
                print('spot', spot, 'beside', anchor, 'failed:', error)
                continue
            open_gripper()
            detach_object(name)
            move_in_direction([0, 0, 1], 0.1)
            used = i
            break
        if used is None:
            set_down_on_table(name)
        detect_objects(object_list=[name, anchor])
        if used is not None and is_next_to(name, anchor):
            return True
        print(name, 'is not next to', anchor, '- trying once more')
        if used is not None and len(spots) > 1:
            spots.pop(used)
    return False


detect_objects()
if not place_beside('blue_mug', 'red_mug', [rim_grasp, top_grasp, side_grasp]):
    raise RuntimeError('the blue mug did not end up next to the red mug')
