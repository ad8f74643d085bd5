# Task: sort the objects on the table by colour: put the white objects on the white plate
# Plan:
# 1. Detect everything. A dict maps the colour word to its plate: 'white' -> 'white_plate'.
# 2. The things on the table are all names except the table, the cabinet and its parts, and the holders
#    (plates, saucers, bowls, baskets), which stay. Select those whose name has the colour as a word.
# 3. Leave out any already on that plate (centre over its footprint); move the rest nearest-to-plate first.
# 4. For each: pick it (top-down when narrow enough, else adaptive from above), lift, place onto the plate.
HOLDER_WORDS = ('plate', 'saucer', 'bowl', 'basket')


def is_loose_object(name):
    return name != 'table' and not name.startswith('cabinet') and not any(w in name for w in HOLDER_WORDS)


def over_footprint(name, holder):
    c = get_object_center_position(name)
    b = get_3d_bbox(holder)
    return b[0] <= c[0] <= b[3] and b[1] <= c[1] <= b[4]


def grasp_pose_for(name):
    box = get_3d_bbox(name)
    narrow = min(box[3] - box[0], box[4] - box[1]) < 0.07
    if narrow and 'mug' not in name and 'cup' not in name:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put(name, receptacle=None, position=None, retreat=0.1):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


detect_objects()
names = get_object_name_list()
plate_for_colour = {'white': 'white_plate'}
for colour, plate in plate_for_colour.items():
    plate_xy = get_object_center_position(plate)[:2]
    chosen = [n for n in names
              if is_loose_object(n) and colour in n.split('_') and not over_footprint(n, plate)]
    chosen.sort(key=lambda n: np.linalg.norm(get_object_center_position(n)[:2] - plate_xy))
    for name in chosen:
        pick(name)
        put(name, receptacle=plate)
