# Task: close the second drawer of the cabinet
# Plan:
# 1. The second drawer is pulled out: push it shut by its handle (cabinet.handle_1).
detect_objects()


def close_drawer(drawer, handle):
    """Pushes `drawer` shut by its `handle`, back along its joint's axis as far as it is open, and lets go."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='prismatic')
    move_in_direction(joint_info['joint_axis'], distance=-joint_info['joint_value'])
    open_gripper()
    detach_object(drawer)


close_drawer('cabinet.drawer_1', 'cabinet.handle_1')
