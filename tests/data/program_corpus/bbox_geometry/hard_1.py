# Swap: the apple goes aside onto the table first, then the banana to the apple's spot and the apple to the
# banana's, the spots read from their boxes (the middle of each box's bottom face).
detect_objects()
apple_box = get_3d_bbox('apple')
banana_box = get_3d_bbox('banana')
apple_spot = [(apple_box[0] + apple_box[3]) / 2, (apple_box[1] + apple_box[4]) / 2, apple_box[2]]
banana_spot = [(banana_box[0] + banana_box[3]) / 2, (banana_box[1] + banana_box[4]) / 2, banana_box[2]]


def move(name, **where):
    open_gripper()
    if name == 'apple':
        grasp(parse_central_lift_grasp_pose(name, description='center'))
    else:
        grasp(parse_adaptive_shape_grasp_pose(name, preferred_approach_direction=[0, 0, -1]))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], 0.1)
    move_to_pose(parse_place_pose(name, **where))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


move('apple', receptacle_name='table')
move('banana', position=apple_spot)
move('apple', position=banana_spot)
