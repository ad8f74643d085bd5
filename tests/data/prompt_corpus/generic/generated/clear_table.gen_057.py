# Task: clear the table by putting every object lying on it into the basket; leave the baskets and plates and saucers where they are
# Plan:
# 1. Look at the scene; the things on the table are all names except the table and furniture.
# 2. Keep apart what stays: baskets, plates, saucers (and bowls), which the gripper cannot pick up anyway.
# 3. The target is the basket; skip anything already standing in a basket.
# 4. Order the rest top-down (highest bottom first), so that anything resting on another thing goes first.
# 5. For each: pick it (mugs and cups from above by their shape, narrow things by a central top grasp,
#    wider ones by the adaptive grasp), lift it above the basket's rim, put it into the basket, move up.
STAYS = ('basket', 'plate', 'saucer', 'bowl')
GRIPPER_SPAN = 0.075  # a little under the smallest opening (8 cm)


def words(name):
    return name.split('_')


def pick(name, lift=0.1):
    open_gripper()
    box = get_3d_bbox(name)
    narrow_side = min(box[3] - box[0], box[4] - box[1])
    if 'mug' in words(name) or 'cup' in words(name):
        pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    elif narrow_side < GRIPPER_SPAN:
        pose = parse_central_lift_grasp_pose(object_name=name, description='center')
    else:
        pose = parse_adaptive_shape_grasp_pose(object_name=name)
    grasp(pose)
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put(name, receptacle=None, position=None):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


def lift_over(name, receptacle):
    # attach_object lifts 5 cm; raise the object's bottom about 3 cm above the receptacle's top
    need = get_3d_bbox(receptacle)[5] + 0.03 - (get_3d_bbox(name)[2] + 0.05)
    return min(max(0.1, need), 0.5)


detect_objects()
names = [n for n in get_object_name_list() if n != 'table' and not n.startswith('cabinet')]
baskets = [n for n in names if 'basket' in words(n)]
basket = baskets[0]
things = [n for n in names
          if not any(word in words(n) for word in STAYS)
          and not any(is_object_in(n, b) for b in baskets)]
things.sort(key=lambda n: -get_3d_bbox(n)[2])

for thing in things:
    pick(thing, lift=lift_over(thing, basket))
    put(thing, receptacle=basket)
