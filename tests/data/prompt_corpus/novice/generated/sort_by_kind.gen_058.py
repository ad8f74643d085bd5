# Task: sort the objects on the table by kind: put the fruits on the red plate.
# Plan:
# 1. The fruits on the table are the plum and the strawberry.
# 2. For each fruit: grasp it from above at its middle, lift it, place it onto the red plate, release it, move up.
detect_objects()
fruits = ['plum', 'strawberry']
for fruit in fruits:
    open_gripper()
    grasp(parse_central_lift_grasp_pose(object_name=fruit, description='center'))
    close_gripper()
    attach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(object_name=fruit, receptacle_name='red_plate'))
    open_gripper()
    detach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
