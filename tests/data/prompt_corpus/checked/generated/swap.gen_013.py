# Task: exchange the places of the white medication bottle and the apple.
# Plan:
# 1. Detect everything and remember where white_medication_bottle and apple stand (centres of their boxes),
#    how big they are and the height of what each stands on (its box bottom), before anything moves.
# 2. Set the bottle aside on a free spot of the table (parse_place_pose with 'table'). Check with a fresh
#    detection that it rests on the table clear of both remembered places (so the apple can go to the bottle's
#    place and the bottle's own old place is not reused); if not, move it to a spot 20 cm off its place that
#    is clear of both.
# 3. Move the apple to where the bottle was; check it ends within 5 cm of that place,
#    standing at the height the other stood.
# 4. Move the bottle to where the apple was; check the same.
# Each pick: a central lift grasp from above; if that fails, or the cameras do not see the object rise with the
# hand, let go and retry once with the adaptive grasp. Each move that fails its check is done once more.


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


def xy_dist(a, b):
    return float(np.hypot(a[0] - b[0], a[1] - b[1]))


def radius(name):
    # Half the horizontal diagonal of the object's box.
    box = get_3d_bbox(name)
    return float(np.hypot(box[3] - box[0], box[4] - box[1])) / 2


def rests_on_table(name):
    return abs(get_3d_bbox(name)[2] - get_3d_bbox('table')[5]) < 0.02


def set_aside(name, keep_clear, clearance):
    # Put the object on a free spot of the table at least `clearance` from every point in keep_clear.
    start = get_object_center_position(name)
    options = [('a free spot of the table', 'table', None)]
    for dx, dy in [(-0.2, 0.0), (0.0, 0.2), (0.0, -0.2), (0.2, 0.0)]:
        spot = [start[0] + dx, start[1] + dy, start[2]]
        if all(xy_dist(spot, p) > clearance for p in keep_clear):
            options.append(('a spot 20 cm off its place', None, spot))
    for label, receptacle, position in options[:3]:
        pick(name)
        place(name, receptacle=receptacle, position=position)
        detect_objects([name])
        centre = get_object_center_position(name)
        if rests_on_table(name) and all(xy_dist(centre, p) > clearance for p in keep_clear):
            return centre
        print('[check] ' + name + ' on ' + label + ' is in the way; moving it again')
    raise RuntimeError('could not set ' + name + ' aside')


def move_to_place(name, target, bottom, tolerance=0.05):
    # Put the object with its centre over target, its bottom at the height the other object stood on (`bottom`);
    # check, one more try if needed.
    for attempt in range(2):
        pick(name)
        place(name, position=target)
        detect_objects([name])
        if xy_dist(get_object_center_position(name), target) <= tolerance and abs(get_3d_bbox(name)[2] - bottom) < 0.02:
            return
        print('[check] ' + name + ' is not at its new place after try ' + str(attempt + 1))
    raise RuntimeError(name + ' could not be moved to its new place')


first, second = 'white_medication_bottle', 'apple'
detect_objects()
first_at = get_object_center_position(first)
second_at = get_object_center_position(second)
first_bottom = get_3d_bbox(first)[2]
second_bottom = get_3d_bbox(second)[2]
clearance = radius(first) + radius(second) + 0.03

set_aside(first, [first_at, second_at], clearance)
move_to_place(second, first_at, first_bottom)
move_to_place(first, second_at, second_bottom)
