# Task: sort the objects on the table by kind: put the boxes into the basket
# Plan:
# 1. Detect everything. A dict maps the kind word to its container: 'box' -> the basket.
# 2. The things on the table are all names except the table, the cabinet and its parts, and the holders
#    (plates, saucers, bowls, baskets), which stay. The boxes are those whose name ends in the word 'box'.
# 3. Leave out any already in the basket; move the rest, ones resting on another thing first, then the nearest
#    to the basket first.
# 4. For each: pick it (top-down when narrow enough, else adaptive from above), lift, place into the basket.
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
table_top = get_3d_bbox('table')[5]
basket = [n for n in names if 'basket' in n][0]
container_for_kind = {'box': basket}
for kind, container in container_for_kind.items():
    container_xy = get_object_center_position(container)[:2]
    chosen = [n for n in names
              if is_loose_object(n) and n.split('_')[-1] == kind and not over_footprint(n, container)]
    chosen.sort(key=lambda n: (get_3d_bbox(n)[2] <= table_top + 0.02,
                               np.linalg.norm(get_object_center_position(n)[:2] - container_xy)))
    for name in chosen:
        pick(name, lift=0.15)
        put(name, receptacle=container)
