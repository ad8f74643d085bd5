# Task: open the second drawer of the cabinet and put the brown medication bottle into it
# Plan:
# 1. Detect everything. Drawers are numbered from the top, so the second drawer is 'cabinet.drawer_1'.
# 2. Its handle: rows are numbered from the top, drawers and doors together; sort them by height (highest
#    first) and the k-th row has 'cabinet.handle_k'.
# 3. Read the drawer's prismatic joint near the handle; grasp the handle horizontally, attach the drawer and
#    pull along +axis until it is open 25 cm (or as far as it goes); release and back away.
# 4. Detect the drawer again (it moved).
# 5. Pick the bottle (top-down when narrow enough, else adaptive from above), lift it, place it into the
#    drawer, release it and move up.
def handle_of(part, names):
    rows = [n for n in names if n.startswith('cabinet.drawer_') or n.startswith('cabinet.door_')]
    rows.sort(key=lambda n: -get_object_center_position(n)[2])
    return 'cabinet.handle_%d' % rows.index(part)


def open_drawer(drawer, handle, target=0.25):
    joint = get_object_joint_info(object_name='cabinet', position=get_object_center_position(handle), type='prismatic')
    distance = min(target, joint['joint_upper']) - joint['joint_value']
    if distance <= 0.01:
        return
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(joint['joint_axis'], distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(joint['joint_axis'], 0.05)


def grasp_pose_for(name):
    box = get_3d_bbox(name)
    narrow = min(box[3] - box[0], box[4] - box[1]) < 0.07
    if narrow and 'mug' not in name and 'cup' not in name:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


def pick(name, lift=0.1):
    open_gripper()
    grasp(grasp_pose_for(name))
    close_gripper()
    attach_object(name)
    move_in_direction([0, 0, 1], lift)


def put(name, receptacle=None, position=None, retreat=0.08):
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], retreat)


detect_objects()
names = get_object_name_list()
ordinal = 1  # "second" drawer, counted from the top from 0
drawer = 'cabinet.drawer_%d' % ordinal
open_drawer(drawer, handle_of(drawer, names))
detect_objects(object_list=[drawer])
for name in ['brown_medication_bottle']:
    pick(name)
    put(name, receptacle=drawer)
