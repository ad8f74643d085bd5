# Task: sort the objects on the table by kind: put the boxes into the basket
# Plan:
# 1. Look at the scene; the objects are all names except the table and furniture.
# 2. The boxes are the objects whose name has the word 'box'; the target is the basket.
# 3. Skip boxes already in the basket; take the others top-down (highest bottom first).
# 4. Before taking a box, set aside on the table anything that is not a box standing on it.
# 5. Pick each box (central top grasp when narrow enough, else the adaptive grasp), lift it above the
#    basket's rim, put it into the basket and move up.
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
basket = [n for n in names if 'basket' in words(n)][0]
boxes = [n for n in names if 'box' in words(n) and not is_object_in(n, basket)]
boxes.sort(key=lambda n: -get_3d_bbox(n)[2])
fixed = ('basket', 'plate', 'saucer', 'bowl')
others = [n for n in names if n not in boxes and not any(word in words(n) for word in fixed)]

for box in boxes:
    for other in others:
        if is_object_in(other, box):
            pick(other)
            put(other, receptacle='table')
    pick(box, lift=lift_over(box, basket))
    put(box, receptacle=basket)
