# Task: sort the objects on the table by colour: put the white objects on the white plate.
# Plan:
# 1. Detect everything. Colours are known only from names: the white objects are those whose name has the word
#    'white'. Leave out the table, the cabinet and its parts, and the plates, saucers, bowls and baskets (they stay
#    where they are and cannot be picked up; the white plate is the target itself). Here that leaves
#    white_medication_bottle.
# 2. For each white object not already on the white plate: pick it from above at mid height, attach it, lift it,
#    place it on the white plate, release it, detach it and move up.

STAYS = ('plate', 'saucer', 'bowl', 'basket')


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


def is_white_movable(name):
    words = name.split('_')
    if name == 'table' or name == 'cabinet' or name.startswith('cabinet.'):
        return False
    return 'white' in words and not any(word in words for word in STAYS)


def already_on(name, receptacle):
    # True when `name`'s centre is over `receptacle`'s box and its bottom is not below the receptacle's bottom.
    c = get_object_center_position(name)
    r = get_3d_bbox(receptacle)
    return r[0] <= c[0] <= r[3] and r[1] <= c[1] <= r[4] and get_3d_bbox(name)[2] >= r[2] - 0.005


detect_objects()
white_objects = [n for n in get_object_name_list() if is_white_movable(n)]
for name in white_objects:
    if already_on(name, 'white_plate'):
        continue
    pick(name)
    place(name, receptacle='white_plate')
