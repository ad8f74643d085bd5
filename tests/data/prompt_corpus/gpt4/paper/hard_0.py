# Task: place all fruits on the table into the white plate.
# Plan:
# 1. Detect all objects.
# 2. The fruits here are the apple and the banana.
# 3. For each fruit: grasp it, lift it, place it on the white ceramic plate, release it, move up.
detect_objects()
fruits = ['apple', 'banana']


def pick_and_place(obj, receptacle):
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(obj))
    close_gripper()
    attach_object(obj)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(obj, receptacle))
    open_gripper()
    detach_object(obj)
    move_in_direction([0, 0, 1], 0.1)


for fruit in fruits:
    pick_and_place(fruit, 'white_ceramic_plate')
