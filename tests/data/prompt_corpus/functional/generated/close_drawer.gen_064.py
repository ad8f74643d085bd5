# Task: close the second drawer of the cabinet.
# Plan:
# 1. The cabinet's rows from the top are drawer, drawer, door: the second drawer is cabinet.drawer_1 and its
#    handle cabinet.handle_1 (cabinet.handle_2 is the door's).
# 2. Read the drawer's prismatic joint near the handle; it is open by joint_value metres (nothing to do if 0).
# 3. Grasp the handle horizontally, close the gripper, attach the drawer.
# 4. Push along -axis by as far as it is open.
# 5. Release the handle and back away along +axis.

DRAWER = 'cabinet.drawer_1'
HANDLE = 'cabinet.handle_1'


def drawer_joint(handle):
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def opening(joint):
    return joint['joint_value']


def close_drawer(drawer, handle):
    joint = drawer_joint(handle)
    distance = opening(joint)
    if distance <= 0.005:
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(joint['joint_axis'], -distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


def main():
    detect_objects()
    close_drawer(DRAWER, HANDLE)


main()
