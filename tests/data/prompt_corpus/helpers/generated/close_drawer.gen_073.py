# Task: close the open drawer.
# Plan:
# 1. The cabinet has two drawers (cabinet.drawer_0 with cabinet.handle_0, cabinet.drawer_1 with cabinet.handle_1)
#    above a door; find which drawer is open from its prismatic joint's value.
# 2. Grasp that drawer's handle horizontally, close the gripper, attach the drawer.
# 3. Push it along -axis by as far as it is open.
# 4. Release the handle and back away along +axis.
def drawer_joint(handle):
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def close_drawer(k):
    drawer = 'cabinet.drawer_%d' % k
    handle = 'cabinet.handle_%d' % k
    joint = drawer_joint(handle)
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(joint['joint_axis'], -joint['joint_value'])
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


detect_objects()
opening = {k: drawer_joint('cabinet.handle_%d' % k)['joint_value'] for k in (0, 1)}
open_k = max(opening, key=opening.get)
close_drawer(open_k)
