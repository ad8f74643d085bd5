def raise_gripper(height):
    pose = get_gripper_pose()
    pose.position.z += height
    move_to_pose(pose)


def put(name, place_pose):
    above = Pose()
    above.position.x = place_pose.position.x
    above.position.y = place_pose.position.y
    above.position.z = place_pose.position.z + 0.1
    above.orientation = place_pose.orientation
    move_to_pose(above)
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    raise_gripper(0.1)



detect_objects()
for name in ['orange', 'toy_bus']:
    open_gripper()
    grasp(parse_adaptive_shape_grasp_pose(name, preferred_position=get_object_center_position(name)))
    close_gripper()
    attach_object(name)
    raise_gripper(0.15)
    put(name, parse_place_pose(name, 'basket_with_fabric_liner'))
