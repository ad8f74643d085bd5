# Task: place all fruits on the table into the white plate.
# Plan:
# 1. Detect the objects and pick out the fruits among them.
# 2. Take the largest fruit (the banana) first, so that the round fruits fill the room left beside it.
# 3. For each fruit: grasp it (round fruits from above at their centre; the curved banana with the adaptive
#    grasp, which finds where its body actually is), lift it, place it on the white plate, release it, move up.
detect_objects()
fruit_kinds = ['banana', 'apple', 'orange', 'lemon', 'peach', 'plum', 'pear']
names = get_object_name_list()
fruits = [kind for kind in fruit_kinds if kind in names]
for fruit in fruits:
    open_gripper()
    if fruit == 'banana':
        grasp_pose = parse_adaptive_shape_grasp_pose(object_name=fruit, preferred_approach_direction=[0, 0, -1])
    else:
        grasp_pose = parse_central_lift_grasp_pose(object_name=fruit, description='center')
    grasp(grasp_pose)
    close_gripper()
    attach_object(fruit)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
    place_pose = parse_place_pose(object_name=fruit, receptacle_name='white_plate')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(fruit)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
