# Task: exchange the position of the apple and the banana on the table.
# Plan:
# 1. Remember where the apple and the banana are now.
# 2. Move the apple out of the way, to a free spot on the table.
# 3. Move the banana to where the apple was.
# 4. Move the apple to where the banana was.
detect_objects(category_list=['apple', 'banana'])
apple_position = get_object_center_position(obj_name='apple')
banana_position = get_object_center_position(obj_name='banana')


def pick(name):
    open_gripper()
    if name == 'banana':  # curved: the adaptive grasp finds where its body is
        grasp_pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    else:
        grasp_pose = parse_central_lift_grasp_pose(object_name=name, description='center')
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


def put_down(name, place_pose):
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


pick('apple')
put_down('apple', parse_place_pose(object_name='apple', receptacle_name='table'))
pick('banana')
put_down('banana', parse_place_pose(object_name='banana', position=apple_position))
pick('apple')
put_down('apple', parse_place_pose(object_name='apple', position=banana_position))
