# Task: sort the objects on the table by kind: put the fruits on the red plate.
# Plan:
# 1. Detect everything. The fruits are the plum and the strawberry.
# 2. For each: grasp it from above at its middle, close, attach, lift.
# 3. Place it on the red plate, release it and move up.
detect_objects()
for n in ['plum', 'strawberry']:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(n, 'center'))
    close_gripper()
    attach_object(n)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(n, 'red_plate'))
    open_gripper()
    detach_object(n)
    move_in_direction([0, 0, 1], 0.1)
