# Task: sort the objects on the table by kind: put the fruits on the red plate.
# Plan:
# 1. Detect all objects.
# 2. The fruits here are the apple and the strawberry (the mugs are not fruits).
# 3. For each fruit: grasp it, lift it, place it on the red plate, release, move up.
detect_objects()
fruits = ['apple', 'strawberry']

for fruit in fruits:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(fruit))
    close_gripper()
    attach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(fruit, 'red_plate'))
    open_gripper()
    detach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
