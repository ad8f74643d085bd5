# Move every object on the table into the basket
for obj in ['orange', 'toy_bus']:
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(obj)
    grasp(grasp_pose)
    close_gripper()
    attach_object(obj)
    place_pose = parse_place_pose(obj, 'basket_with_fabric_liner')
    move_to_pose(place_pose)
    open_gripper()
    detach_object(obj)
