# Task: close the open drawer
# Plan:
# 1. Detect everything. The drawers are the names 'cabinet.drawer_k'.
# 2. Handles are numbered by rows from the top, drawers and doors together: sort the drawers and doors by
#    height (highest first); the k-th of them has 'cabinet.handle_k'.
# 3. For each drawer read its prismatic joint near its handle; the open one is the one opened farthest.
# 4. Grasp its handle horizontally, attach the drawer, push it along -axis by as far as it is open.
# 5. Release the handle and back away along +axis.
def handle_of(part, names):
    rows = [n for n in names if n.startswith('cabinet.drawer_') or n.startswith('cabinet.door_')]
    rows.sort(key=lambda n: -get_object_center_position(n)[2])
    return 'cabinet.handle_%d' % rows.index(part)


def drawer_joint(handle):
    return get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')


def move_drawer(drawer, handle, distance):
    # distance > 0 pulls it open, < 0 pushes it shut
    joint = drawer_joint(handle)
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(joint['joint_axis'], distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


detect_objects()
names = get_object_name_list()
drawers = [n for n in names if n.startswith('cabinet.drawer_')]
opening = {d: drawer_joint(handle_of(d, names))['joint_value'] for d in drawers}
open_drawer = max(opening, key=opening.get)
if opening[open_drawer] > 0.005:
    move_drawer(open_drawer, handle_of(open_drawer, names), -opening[open_drawer])
