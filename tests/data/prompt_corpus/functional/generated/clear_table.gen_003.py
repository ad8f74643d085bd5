# Task: clear the table by putting every object lying on it into the basket; leave the baskets, bowls and
# plates where they are.
# Plan:
# 1. Detect the scene. The things to move are all names except the table, furniture and the kinds that
#    stay (baskets, bowls, plates, saucers), and except anything already inside the basket.
# 2. Order them from the highest bottom down, so that something resting on another thing goes first.
# 3. For each: pick it (mugs and cups by their rim from above, others with a top-down grasp at the middle),
#    lift it over the basket's rim, place it into the basket, release, move up.

BASKET = 'basket'
STAYING_KINDS = ('basket', 'bowl', 'plate', 'saucer')
VESSEL_KINDS = ('mug', 'cup')


def kind_of(name):
    return name.split('_')[-1]


def is_furniture(name):
    return name == 'table' or name == 'cabinet' or name.startswith('cabinet.')


def stays(name):
    return kind_of(name) in STAYING_KINDS


def inside(name, container):
    c = get_object_center_position(name)
    box = get_3d_bbox(container)
    return box[0] <= c[0] <= box[3] and box[1] <= c[1] <= box[4] and box[2] <= c[2] <= box[5]


def things_to_clear(names, container):
    return [n for n in names if not is_furniture(n) and not stays(n) and not inside(n, container)]


def top_down_order(names):
    return sorted(names, key=lambda n: get_3d_bbox(n)[2], reverse=True)


def lift_over(name, obstacle, margin=0.05, minimum=0.1):
    return max(minimum, get_3d_bbox(obstacle)[5] - get_3d_bbox(name)[2] + margin)


def grasp_pose_for(name):
    if kind_of(name) in VESSEL_KINDS:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def place(name, pose, retreat=0.1):
    move_to_pose(pose)
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


def put_into(name, container):
    pick(name, lift_over(name, container))
    place(name, parse_place_pose(object_name=name, receptacle_name=container))


def main():
    detect_objects()
    for name in top_down_order(things_to_clear(get_object_name_list(), BASKET)):
        put_into(name, BASKET)


main()
