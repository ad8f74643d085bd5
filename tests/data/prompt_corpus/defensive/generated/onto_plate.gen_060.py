# Task: put the medication bottle on the white saucer.
# Plan:
# 1. Look at the scene (the cabinet plays no part).
# 2. Pick the medication bottle: a top-down grasp at its middle first; if a grasp tool raises or the fingers
#    close on nothing, look again and fall back to the adaptive grasp, then to a horizontal one. Lift it.
# 3. Place it onto the white saucer, let go, move up; if placing raises, look again and try once more,
#    else set the bottle down on the table so that the hand is free.
# 4. Look again and check that the bottle's centre is over the saucer; if not, pick and place it once more.


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


def over(name, support, margin=0.01):
    # True when the object's centre lies above the support's box in x and y.
    centre = get_object_center_position(name)
    box = get_3d_bbox(support)
    return box[0] - margin <= centre[0] <= box[3] + margin and box[1] - margin <= centre[1] <= box[4] + margin


def put(name, receptacle, grasp_tools, check=over, lift=0.1):
    # Pick and place, then look again and check where the object ended up; one retry if it is not there.
    for attempt in range(2):
        if not pick(name, grasp_tools, lift):
            return False
        placed = place(name, receptacle=receptacle)
        detect_objects(object_list=[name, receptacle])
        if placed and check(name, receptacle):
            return True
        print(name, 'did not end up in/on', receptacle, '- trying once more')
    return False


detect_objects()
if not put('medication_bottle', 'white_saucer', [top_grasp, rim_grasp, side_grasp]):
    raise RuntimeError('the medication bottle did not end up on the white saucer')
