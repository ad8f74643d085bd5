# Fruits on the table: apple and banana
fruits = ['apple', 'banana']
for fruit in fruits:
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(fruit)
    grasp(grasp_pose)
    close_gripper()
    attach_object(fruit)
    place_pose = parse_place_pose(fruit, 'white_ceramic_plate')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(fruit)
