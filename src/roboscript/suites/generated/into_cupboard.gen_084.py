# Task: open the cabinet door, then place the blue box inside the cabinet
# Plan:
# 1. The door turns on its hinge: swing it open by its handle (cabinet.handle_0).
# 2. Things go in through the door under the shelf above, so grip the blue box from the side and put it in; the hand backs out the way it came.
detect_objects()


def open_door(door, handle):
    """Swings `door` open by its `handle`, along an arc about its hinge, and lets go of the handle."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='revolute')
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint_info['joint_axis'],
                                          joint_position=joint_info['joint_position'], n=20, angle=70)
    follow_path(path)
    open_gripper()
    detach_object(door)


def pick_from_side(name):
    """Grasps `name` from the side, fingers level, and lifts it clear of what is around it."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name))
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


def put(name, place_pose):
    """Carries the held `name` to `place_pose`, lets go of it and moves the hand up and away."""
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)


open_door('cabinet.door_0', 'cabinet.handle_0')
pick_from_side('blue_box')
put('blue_box', parse_place_pose(object_name='blue_box', receptacle_name='cabinet.door_0'))
