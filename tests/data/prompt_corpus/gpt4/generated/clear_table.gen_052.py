# Task: clear the table by putting every object lying on it into the basket;
#       leave the baskets and plates where they are.
# Plan:
# 1. Detect all objects.
# 2. The objects to move are all names except the table, the basket and the plates:
#    gelatin_box, red_mug, toy_car, apple.
# 3. For each object: grasp it with the adaptive grasp, lift it, place it into the basket, release, move up.
detect_objects()

objects_to_move = [name for name in get_object_name_list()
                   if name != 'table' and not name.startswith('cabinet')
                   and 'basket' not in name and 'plate' not in name]


def pick_and_place(obj, receptacle):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, receptacle))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


for obj in objects_to_move:
    pick_and_place(obj, 'basket')
