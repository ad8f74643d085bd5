# Task: put the blue cup into the second drawer; the drawer is closed, open it first
# Plan:
# 1. The drawer is closed: pull it open by its handle (cabinet.handle_1).
# 2. Pick up the blue cup and put it into the cabinet's drawer 1.
detect_objects()


def open_drawer(drawer, handle):
    """Pulls `drawer` open by its `handle`, along its joint's axis, and lets go of the handle."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='prismatic')
    axis = joint_info['joint_axis']
    move_in_direction(axis, distance=0.22)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, distance=0.03)


def pick(name):
    """Grasps `name` from above where its shape allows, and lifts it clear of what is around it."""
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


def put(name, place_pose):
    """Carries the held `name` to `place_pose`, lets go of it and moves the hand up and away."""
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


open_drawer('cabinet.drawer_1', 'cabinet.handle_1')
pick('blue_cup')
put('blue_cup', parse_place_pose(object_name='blue_cup', receptacle_name='cabinet.drawer_1'))
