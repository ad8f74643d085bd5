# Task: put the peach into the top drawer; the drawer is closed, open it first.
# Plan:
# 1. Detect everything. The top drawer is cabinet.drawer_0 (three drawers, no door), its handle cabinet.handle_0.
# 2. Open the drawer: read its prismatic joint near the handle, grasp the handle level, close the gripper, attach
#    the drawer, pull along +axis to nearly its full travel (1 cm short of the stop, at most 30 cm), release, detach
#    and back away along +axis.
# 3. Detect again (the drawer moved) and re-read how far it is open; if it stopped more than 3 cm short, pull the
#    rest once more. Give up if it is still barely open (under 5 cm).
# 4. Pick the peach from above at its middle height and lift it.
# 5. Place it into the open drawer, release it, detach it and move up.

MAX_PULL = 0.30   # metres of opening at most (the arm pulls towards itself)
SHORT_OK = 0.03   # metres short of the goal that count as done
MIN_OPEN = 0.05   # metres open below which the drawer counts as not opened


def drawer_joint(drawer, handle):
    # Look again (the drawer may have moved) and read the drawer's slide near its handle.
    detect_objects()
    return get_object_joint_info(object_name=drawer, position=get_object_center_position(handle), type='prismatic')


def move_drawer(drawer, handle, axis, distance):
    # Grasp the handle, move the drawer by `distance` along its axis (+ opens, - shuts), let go, back away.
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    move_in_direction(axis, distance)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, 0.08)   # +axis points out of the cabinet: away from the handle


def open_drawer(drawer, handle, tries=2):
    # Open the drawer to nearly its full travel; returns how far it is open.
    for _ in range(tries):
        joint = drawer_joint(drawer, handle)
        goal = min(joint['joint_upper'] - 0.01, MAX_PULL)
        if joint['joint_value'] >= goal - SHORT_OK:
            return joint['joint_value']
        move_drawer(drawer, handle, joint['joint_axis'], goal - joint['joint_value'])
    return drawer_joint(drawer, handle)['joint_value']


def pick(name, lift=0.1):
    # Grasp `name` from above, attach it and lift it; a second try with the adaptive grasp if the first held nothing.
    for attempt in range(2):
        open_gripper()
        if attempt == 0:
            try:
                pose = parse_central_lift_grasp_pose(object_name=name, description='center')
            except GraspError:
                pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        else:
            pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
        grasp(pose)
        close_gripper()
        try:
            attach_object(name)
        except GraspError:
            if attempt == 1:
                raise
            open_gripper()
            move_in_direction([0, 0, 1], 0.1)
            detect_objects([name])
            continue
        move_in_direction([0, 0, 1], lift)
        return


def place(name, receptacle=None, position=None):
    # Set the held `name` down in/on `receptacle` or at `position`, let go and move up.
    move_to_pose(parse_place_pose(object_name=name, receptacle_name=receptacle, position=position))
    open_gripper()
    detach_object(name)
    move_in_direction([0, 0, 1], 0.1)


detect_objects()
opened = open_drawer('cabinet.drawer_0', 'cabinet.handle_0')
if opened < MIN_OPEN:
    raise FailureError('the top drawer opened only %.2f m' % opened)
pick('peach')
place('peach', receptacle='cabinet.drawer_0')
