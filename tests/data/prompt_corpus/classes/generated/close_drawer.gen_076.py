# Task: close the open drawer.
# Plan:
# 1. Look at the scene. Rows from the top: cabinet.drawer_0 (handle_0), cabinet.drawer_1 (handle_1),
#    cabinet.door_0 (handle_2); only the two drawers can be the open drawer.
# 2. Read each drawer's prismatic joint near its handle and take the one that is open (the largest joint value).
# 3. Grasp its handle horizontally, close the gripper, attach the drawer.
# 4. Push along -axis by as far as it is open, release, detach, back away along +axis.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self):
        self.held = None

    def look(self, names=None):
        detect_objects(object_list=names)

    def drawer_joint(self, handle, drawer):
        return get_object_joint_info(object_name=drawer, position=get_object_center_position(handle), type='prismatic')

    def find_open_drawer(self, drawers):
        # drawers: list of (handle, drawer); returns the most open one, or None if all are shut.
        found, most_open = None, 0.01
        for handle, drawer in drawers:
            value = self.drawer_joint(handle, drawer)['joint_value']
            if value > most_open:
                found, most_open = (handle, drawer), value
        return found

    def hold_handle(self, handle, part):
        open_gripper()
        grasp(parse_horizontal_grasp_pose(object_name=handle))
        close_gripper()
        attach_object(part)
        self.held = part

    def close_drawer(self, handle, drawer):
        joint = self.drawer_joint(handle, drawer)
        self.hold_handle(handle, drawer)
        move_in_direction(joint['joint_axis'], -joint['joint_value'])
        open_gripper()
        detach_object(drawer)
        self.held = None
        move_in_direction(joint['joint_axis'], 0.05)


robot = Robot()
robot.look()
open_drawer = robot.find_open_drawer([('cabinet.handle_0', 'cabinet.drawer_0'), ('cabinet.handle_1', 'cabinet.drawer_1')])
if open_drawer is not None:
    robot.close_drawer(open_drawer[0], open_drawer[1])
