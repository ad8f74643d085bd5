# Task: exchange the places of the pear and the rubiks cube.
# Plan:
# 1. Look at the scene and remember where the pear and the rubiks cube are before anything moves.
# 2. Move the pear out of the way: to a free spot 20 cm from it (towards the robot first) that keeps clear of both
#    remembered places, else anywhere free on the table; look again and check its old place is clear; retry once.
# 3. Move the rubiks cube to where the pear was; look again and check it is within 5 cm of that spot; retry once.
# 4. Move the pear to where the rubiks cube was; look again and check it the same way; retry once.
#    Every pick: top-down grasp at the middle first; if a grasp tool raises or the fingers close on nothing, look
#    again and fall back to the adaptive grasp, then to a horizontal one. If placing raises, look again and try
#    once more, else set the object down on the table so that the hand is free.


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


def distance_xy(a, b):
    return float(np.linalg.norm(np.array(a, dtype=float)[:2] - np.array(b, dtype=float)[:2]))


def free_spot(near, avoid, clearance):
    # A spot 20 cm from `near` - towards the robot first, then left, right, away - at least `clearance` from every
    # point in `avoid`; None if there is none.
    for dx, dy in [(-0.2, 0.0), (0.0, 0.2), (0.0, -0.2), (0.2, 0.0)]:
        spot = [near[0] + dx, near[1] + dy, near[2]]
        if all(distance_xy(spot, point) >= clearance for point in avoid):
            return spot
    return None


def move_aside(name, away_from, grasp_tools, clearance):
    # Moves the object out of the way (to a free spot near it, else to any free spot on the table); looks again and
    # checks that it is at least `clearance` from every point in away_from; one retry.
    spot = free_spot(get_object_center_position(name), away_from, clearance + 0.05)
    for attempt in range(2):
        if not pick(name, grasp_tools):
            return False
        if spot is not None and attempt == 0:
            place(name, position=spot)
        else:
            place(name, receptacle='table')
        detect_objects(object_list=[name])
        centre = get_object_center_position(name)
        if all(distance_xy(centre, point) >= clearance for point in away_from):
            return True
        print(name, 'is still in the way - trying once more')
    return False


def move_to_spot(name, spot, grasp_tools, tolerance=0.05):
    # Moves the object so that its centre is above `spot`; looks again and checks where it ended up; one retry.
    for attempt in range(2):
        if not pick(name, grasp_tools):
            return False
        placed = place(name, position=spot)
        detect_objects(object_list=[name])
        if placed and distance_xy(get_object_center_position(name), spot) <= tolerance:
            return True
        print(name, 'is not where it should be - trying once more')
    return False


detect_objects()
pear_at = list(get_object_center_position('pear'))
cube_at = list(get_object_center_position('rubiks_cube'))
tools = [top_grasp, rim_grasp, side_grasp]
if not move_aside('pear', [pear_at, cube_at], tools, clearance=0.1):
    raise RuntimeError('could not move the pear out of the way')
if not move_to_spot('rubiks_cube', pear_at, tools):
    raise RuntimeError('the rubiks cube did not end up where the pear was')
if not move_to_spot('pear', cube_at, tools):
    raise RuntimeError('the pear did not end up where the rubiks cube was')
