# Task: open the second drawer of the cabinet and put the baseball into it.
# Plan:
# 1. The cabinet has three drawers, numbered from the top: the second is cabinet.drawer_1 with cabinet.handle_1
#    (checked: the handle whose height lies within the drawer's box).
# 2. Read the drawer's prismatic joint near the handle; grasp the handle, attach the drawer and pull along
#    +axis until it is open 0.9 of its travel (at most 25 cm); release and back away along +axis.
# 3. Detect again; from the drawer's box, the handle and the opening, compute the middle of the part of the
#    drawer now outside the cabinet; check that the baseball fits in that length.
# 4. Grasp the baseball from above, lift it, place it at that point in cabinet.drawer_1, release, move up.
# 5. Detect again and check that the ball's centre lies within the drawer's box.


def box_centre(box):
    return np.array([(box[0] + box[3]) / 2, (box[1] + box[4]) / 2, (box[2] + box[5]) / 2])


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


def top_grasp_pose(name):
    try:
        return parse_central_lift_grasp_pose(object_name=name, description='center')
    except GraspError:
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])


detect_objects()
drawer = 'cabinet.drawer_1'
handle = handle_of(drawer, 'cabinet.handle_1')
handle_at = get_object_center_position(handle)
joint = get_object_joint_info(object_name=drawer, position=handle_at, type='prismatic')
axis = np.array(joint['joint_axis'], dtype=float)
wanted = min(0.9 * joint['joint_upper'], 0.25)
pull = wanted - joint['joint_value']
print('drawer open', round(float(joint['joint_value']), 3), 'of', round(float(joint['joint_upper']), 3),
      'm; pulling', round(float(pull), 3), 'm')

# Open the drawer.
if pull > 0.01:
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(axis, pull)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, 0.05)

# Measure the open drawer: the exposed part lies between the cabinet's front (the drawer's front pulled back by
# the opening) and the inside of the drawer's front panel (about 2 cm thick).
detect_objects()
handle_at = get_object_center_position(handle)
joint = get_object_joint_info(object_name=drawer, position=handle_at, type='prismatic')
opened = joint['joint_value']
dbox = get_3d_bbox(drawer)
centre = box_centre(dbox)
flat = np.array([axis[0], axis[1], 0.0])
flat = flat / np.linalg.norm(flat)
half_depth = 0.5 * (abs(flat[0]) * (dbox[3] - dbox[0]) + abs(flat[1]) * (dbox[4] - dbox[1]))
# The drawer's front face along the axis; if its box includes the handle, the handle's centre is nearer the panel.
front = min(np.dot(centre, flat) + half_depth, np.dot(handle_at, flat))
wall = 0.02
middle = front - (opened + wall) / 2
target = centre + flat * (middle - np.dot(centre, flat))
target[2] = dbox[2]
ball = get_3d_bbox('baseball')
ball_size = max(ball[3] - ball[0], ball[4] - ball[1])
print('drawer open', round(float(opened), 3), 'm; target', np.round(target, 3), 'ball', round(float(ball_size), 3), 'm')
if opened - wall < ball_size:
    print('warning: the open part of the drawer may be shorter than the ball')

# Put the ball in.
open_gripper()
grasp(top_grasp_pose('baseball'))
close_gripper()
attach_object('baseball')
move_in_direction([0, 0, 1], 0.1)
move_to_pose(parse_place_pose(object_name='baseball', receptacle_name=drawer, position=list(target)))
open_gripper()
detach_object('baseball')
move_in_direction([0, 0, 1], 0.08)

detect_objects()
dbox = get_3d_bbox(drawer)
c = get_object_center_position('baseball')
inside = dbox[0] <= c[0] <= dbox[3] and dbox[1] <= c[1] <= dbox[4]
print('baseball now at', np.round(c, 3), 'within the drawer box:', inside)
