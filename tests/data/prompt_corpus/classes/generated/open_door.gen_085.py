# Task: open the cabinet door wide.
# Plan:
# 1. Look at the scene. The query lists cabinet.door_0 before cabinet.drawer_0, so the door is the top row
#    and its handle is cabinet.handle_0 (cabinet.handle_1 is the drawer's).
# 2. Read the door's revolute joint near its handle: hinge axis, a point on it, how far it is open and how far
#    it opens at most.
# 3. Grasp the handle horizontally, close the gripper, attach the door.
# 4. Swing the hand about the hinge from its present pose, in small steps, to nearly the door's limit ("wide").
# 5. Release the handle, detach the door and back the hand out along its approach axis.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self):
        self.held = None

    def look(self, names=None):
        detect_objects(object_list=names)

    def approach_axis(self, pose):
        # The gripper's approach (z) axis from its quaternion.
        x, y, z, w = pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w
        return np.array([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)])

    def hold_handle(self, handle, part):
        open_gripper()
        grasp(parse_horizontal_grasp_pose(object_name=handle))
        close_gripper()
        attach_object(part)
        self.held = part

    def let_go_of_door(self):
        open_gripper()
        detach_object(self.held)
        self.held = None
        move_in_direction(-self.approach_axis(get_gripper_pose()), 0.08)

    def open_door(self, handle, door, margin=5):
        joint = get_object_joint_info(object_name=door, position=get_object_center_position(handle), type='revolute')
        angle = joint['joint_upper'] - margin - joint['joint_value']
        if angle <= 0:
            return
        self.hold_handle(handle, door)
        path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                              joint_position=joint['joint_position'], n=max(10, int(angle / 3)),
                                              angle=angle)
        follow_path(path)
        self.let_go_of_door()


robot = Robot()
robot.look()
robot.open_door('cabinet.handle_0', 'cabinet.door_0')
