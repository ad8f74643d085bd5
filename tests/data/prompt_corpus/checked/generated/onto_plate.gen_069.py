# Task: place the toy car onto the white plate.
# Plan:
# 1. Detect everything. The object to move is toy_car, the receptacle white_plate (the plate stays where it is;
#    the blue saucer, the box, the bottle, the mug and the cabinet are not involved).
# 2. Pick the car: a central lift grasp from above (it grips a long object across); if that grasp fails, or the
#    cameras do not see the car rise with the hand, let go and retry once with the adaptive grasp.
# 3. Place it onto the white plate with parse_place_pose, release it and move up.
# 4. Check with a fresh detection that the car's centre lies over the plate and it rests above the table top;
#    if not, pick and place it once more.


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


def place(name, receptacle):
    # Set the held object down where parse_place_pose says, let go and move up.
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def lies_on_plate(name, plate, margin=0.01):
    # Fresh look: the object's centre is over the plate's box and the object is not down on the table beside it.
    detect_objects([name, plate])
    centre = get_object_center_position(name)
    box = get_3d_bbox(plate)
    over = box[0] - margin <= centre[0] <= box[3] + margin and box[1] - margin <= centre[1] <= box[4] + margin
    above_table = get_3d_bbox(name)[2] > get_3d_bbox('table')[5] + 0.003
    return bool(over and above_table)


def transfer(name, receptacle):
    # Pick and place, then check the result; one more try if the check fails.
    for attempt in range(2):
        pick(name)
        place(name, receptacle)
        if lies_on_plate(name, receptacle):
            return
        print('[check] ' + name + ' is not on ' + receptacle + ' after try ' + str(attempt + 1))
    raise RuntimeError(name + ' could not be put onto ' + receptacle)


detect_objects()
transfer('toy_car', 'white_plate')
