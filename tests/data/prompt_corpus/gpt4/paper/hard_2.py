# Task: clear the table by moving all table objects into the basket.
# Plan:
# 1. Detect all objects.
# 2. The objects on the table are all names except the table, the cabinet (and its parts)
#    and the basket itself: orange, toy_bus.
# 3. For each object: grasp it, lift it above the basket, place it into the basket, release, move up.
detect_objects()
basket = 'basket_with_fabric_liner'
table_objects = [n for n in get_object_name_list()
                 if n not in ['table', basket] and not n.startswith('cabinet')]

for obj in table_objects:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.15)
    move_to_pose(parse_place_pose(obj, basket))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
