# Task: sort the objects on the table by kind: put the blocks on the green plate.
# Plan:
# 1. The blocks are the objects whose names end in '_block' (here the green block).
# 2. For each block: grasp it from above, lift it, place it on the green plate, release it, move up.
detect_objects()
blocks = [name for name in get_object_name_list() if name.endswith('_block')]
for block in blocks:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=block, description='center'))
    close_gripper()
    attach_object(block)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=block, receptacle_name='green_plate'))
    open_gripper()
    detach_object(block)
    move_in_direction([0, 0, 1], 0.1)
