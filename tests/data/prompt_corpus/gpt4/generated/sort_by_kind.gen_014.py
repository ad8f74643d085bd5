# Task: sort the objects on the table by kind: put the boxes into the basket.
# Plan:
# 1. Detect all objects.
# 2. The boxes are the objects whose names end with '_box': yellow_box, tea_box.
# 3. For each box: grasp it, lift it above the basket, place it into the basket, release, move up.
detect_objects()
boxes = [name for name in get_object_name_list() if name.endswith('_box')]

for box in boxes:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(box))
    close_gripper()
    attach_object(box)
    move_in_direction([0, 0, 1], 0.15)
    move_to_pose(parse_place_pose(box, 'basket'))
    open_gripper()
    detach_object(box)
    move_in_direction([0, 0, 1], 0.1)
