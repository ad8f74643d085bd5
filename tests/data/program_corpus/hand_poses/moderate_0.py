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



def pull_drawer(handle, drawer, distance):
    open_gripper()
    grasp(parse_horizontal_grasp_pose(handle))
    close_gripper()
    attach_object(drawer)
    axis = get_object_joint_info(drawer, get_object_center_position(handle))['joint_axis']
    pose = get_gripper_pose()
    pose.position.x += axis[0] * distance
    pose.position.y += axis[1] * distance
    pose.position.z += axis[2] * distance
    move_to_pose(pose)
    open_gripper()
    detach_object(drawer)
    back = get_gripper_pose()
    back.position.x += axis[0] * 0.05
    back.position.y += axis[1] * 0.05
    move_to_pose(back)


detect_objects()
pull_drawer('cabinet.handle_1', 'cabinet.drawer_1', 0.2)
for box in ['white_and_pink_box', 'brown_box']:
    grasp(parse_adaptive_shape_grasp_pose(box, preferred_position=get_object_center_position(box)))
    close_gripper()
    attach_object(box)
    raise_gripper(0.1)
    put(box, parse_place_pose(box, 'cabinet.drawer_1'))
