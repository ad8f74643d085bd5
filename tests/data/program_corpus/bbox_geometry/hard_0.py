# Each fruit goes to the plate, the second beside the first: positions from the plate's box.
detect_objects()
plate = get_3d_bbox('white_ceramic_plate')
cx, cy = (plate[0] + plate[3]) / 2, (plate[1] + plate[4]) / 2
for fruit in ['apple', 'banana']:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(fruit, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(fruit, receptacle_name='white_ceramic_plate'))
    open_gripper()
    detach_object(fruit)
    move_in_direction([0, 0, 1], 0.1)
