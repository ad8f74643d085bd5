# The orange from the side, the toy bus from above; both into the basket.
detect_objects()
basket = 'basket_with_fabric_liner'
for name, grasp_pose in [('orange', lambda: parse_horizontal_grasp_pose('orange')),
                         ('toy_bus', lambda: parse_central_lift_grasp_pose('toy_bus'))]:
    open_gripper()
    grasp(grasp_pose())
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.12)
    move_to_pose(parse_place_pose(name, basket))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)
