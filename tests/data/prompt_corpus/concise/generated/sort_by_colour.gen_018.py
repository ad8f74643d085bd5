# Task: sort the objects on the table by colour: red objects on the red plate, green objects on the green plate.
# Plan:
# 1. Red: the red block. Green: the green block and the lime. The plates stay; the other objects are neither colour.
# 2. For each: grasp it from above, lift it, place it onto its plate, release it, move up.
detect_objects()
destination = {'red_block': 'red_plate', 'green_block': 'green_plate', 'lime': 'green_plate'}
for name, plate in destination.items():
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=name, description='center'))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=plate))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
