def move_in_direction(direction, distance=0.1):
    current_pose = get_gripper_pose()
    target_pose = Pose()
    target_pose.position.x = direction[0] * distance + current_pose.position.x
    target_pose.position.y = direction[1] * distance + current_pose.position.y
    target_pose.position.z = direction[2] * distance + current_pose.position.z
    target_pose.orientation = current_pose.orientation
    move_to_pose(target_pose)


def pick(object_name):
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=object_name)
    grasp(grasp_pose)
    close_gripper()
    attach_object(object_name)


def place(object_name, receptacle_name=None, position=None):
    if position is None:
        place_pose = parse_place_pose(object_name=object_name, receptacle_name=receptacle_name)
    else:
        place_pose = parse_place_pose(object_name=object_name, position=position)
    move_to_pose(place_pose)
    open_gripper()
    detach_object(object_name)
    move_in_direction([0, 0, 1], 0.1)



FRUITS = ('apple', 'banana', 'orange', 'lemon', 'pear', 'peach')
detect_objects()
for name in get_object_name_list():
    if name in FRUITS:
        pick(name)
        place(name, 'white_ceramic_plate')
