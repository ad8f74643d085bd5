# Task: clear the table by putting every object lying on it into the basket; leave the baskets and plates and saucers where they are
# Plan:
# 1. Detect everything. The basket is the name containing 'basket'.
# 2. The things to clear are all names except the table, the cabinet and its parts, and the holders
#    (plates, saucers, bowls, baskets), which stay where they are.
# 3. Leave out anything already in the basket (its centre over the basket's footprint).
# 4. Order: things resting on another thing first (bottom above the table top), then the nearest to the basket.
# 5. For each: pick it (top-down when narrow enough, else the adaptive grasp from above), lift it,
#    place it into the basket, release it and move up.
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
basket = [n for n in names if 'basket' in n][0]
table_top = get_3d_bbox('table')[5]
basket_xy = get_object_center_position(basket)[:2]

to_clear = [n for n in names if is_loose_object(n) and not over_footprint(n, basket)]


def order_key(name):
    resting_on_something = get_3d_bbox(name)[2] > table_top + 0.02
    distance = np.linalg.norm(get_object_center_position(name)[:2] - basket_xy)
    return (not resting_on_something, distance)


for name in sorted(to_clear, key=order_key):
    pick(name, lift=0.15)
    put(name, receptacle=basket)
