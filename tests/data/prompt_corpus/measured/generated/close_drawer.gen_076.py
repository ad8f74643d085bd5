# Task: close the open drawer.
# Plan:
# 1. The cabinet's rows from the top are drawer_0, drawer_1, door_0: the drawers' handles are cabinet.handle_0
#    and cabinet.handle_1 (checked: the handle whose height lies within each drawer's box).
# 2. For each drawer read its prismatic joint near its handle; the open one has the largest joint_value
#    (more than 1 cm).
# 3. Grasp that drawer's handle horizontally, attach the drawer, push along -axis by its joint_value.
# 4. Detect again; if it is still more than 1 cm open, push the rest. Release and back away along +axis.


def handle_of(part, default):
    # The handle whose centre height lies within the part's box; the numbering rule's answer otherwise.
    pbox = get_3d_bbox(part)
    found = [n for n in get_object_name_list()
             if n.startswith('cabinet.handle_') and pbox[2] <= get_object_center_position(n)[2] <= pbox[5]]
    if len(found) == 1:
        if found[0] != default:
            print('by height the handle of', part, 'is', found[0], 'not', default)
        return found[0]
    return default


def drawer_joint(drawer, handle):
    return get_object_joint_info(object_name=drawer, position=get_object_center_position(handle), type='prismatic')


detect_objects()
defaults = {'cabinet.drawer_0': 'cabinet.handle_0', 'cabinet.drawer_1': 'cabinet.handle_1'}
state = []
for drawer in defaults:
    handle = handle_of(drawer, defaults[drawer])
    joint = drawer_joint(drawer, handle)
    print(drawer, '(', handle, ') open by', round(float(joint['joint_value']), 3), 'm')
    state.append((joint['joint_value'], drawer, handle, joint))
opened, drawer, handle, joint = max(state, key=lambda s: s[0])

if opened < 0.01:
    print('no drawer is open')
else:
    print('closing', drawer)
    axis = np.array(joint['joint_axis'], dtype=float)
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(axis, -opened)
    detect_objects()
    rest = drawer_joint(drawer, handle)['joint_value']
    if rest > 0.01:
        print('still open by', round(float(rest), 3), 'm; pushing the rest')
        move_in_direction(axis, -rest)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, 0.05)
    detect_objects()
    print(drawer, 'now open by', round(float(drawer_joint(drawer, handle)['joint_value']), 3), 'm')
