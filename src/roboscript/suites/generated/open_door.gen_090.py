# Task: open the cabinet door wide
# Plan:
# 1. The door turns on its hinge: swing it open by its handle (cabinet.handle_0).
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


open_door('cabinet.door_0', 'cabinet.handle_0')
