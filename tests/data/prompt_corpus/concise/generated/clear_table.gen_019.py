# Task: clear the table by putting every object lying on it into the basket; leave the baskets and bowls where they are.
# Plan:
# 1. The objects to move are all names except the table, the cabinet and its parts, and the things that stay
#    (baskets, bowls, plates, saucers).
# 2. For each: grasp it (cups and things too wide for a top grasp with the adaptive grasp from above,
#    others from above at the middle), lift it, place it into the basket, release, move up.
detect_objects()
stay = ('basket', 'bowl', 'plate', 'saucer')
items = [n for n in get_object_name_list()
         if n != 'table' and not n.startswith('cabinet') and not any(s in n for s in stay)]

for name in items:
    open_gripper()
    b = get_3d_bbox(name)
    if 'cup' in name or 'mug' in name or min(b[3] - b[0], b[4] - b[1]) > 0.075:
        grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
    else:
        grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.15)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name='basket'))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
