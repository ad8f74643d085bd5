# Task: open the cabinet door, then place the blue box inside the cabinet.
# Plan:
# 1. Look at the scene. The query lists cabinet.door_0 before cabinet.drawer_0, so the door is the top row and its
#    handle is cabinet.handle_0.
# 2. Read the door's revolute joint near its handle, grasp the handle horizontally, attach the door, swing the
#    hand about the hinge to 90 degrees open (placing behind a door needs at least 40), release, back out.
# 3. Look again (the door moved) and check that the door is open at least 40 degrees; give up otherwise.
# 4. Grasp the blue box level with the horizontal grasp (needed for carrying it into the compartment), lift it.
# 5. Get a place pose in the compartment behind cabinet.door_0, move there, release and detach; the hand backs
#    out the way it came, so no move up inside the cabinet.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, lift_height=0.1):
        self.held = None
        self.lift_height = lift_height

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

    def open_door(self, handle, door, target_angle):
        joint = get_object_joint_info(object_name=door, position=get_object_center_position(handle), type='revolute')
        angle = min(target_angle, joint['joint_upper']) - joint['joint_value']
        if angle > 0:
            self.hold_handle(handle, door)
            path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint['joint_axis'],
                                                  joint_position=joint['joint_position'], n=max(10, int(angle / 3)),
                                                  angle=angle)
            follow_path(path)
            open_gripper()
            detach_object(door)
            self.held = None
            move_in_direction(-self.approach_axis(get_gripper_pose()), 0.08)
        # The door moved: measure it anew.
        self.look()
        return get_object_joint_info(object_name=door, position=joint['joint_position'], type='revolute')['joint_value']

    def pick_level(self, name):
        open_gripper()
        grasp(parse_horizontal_grasp_pose(object_name=name, approach_direction=[1, 0, 0]))
        close_gripper()
        attach_object(name)
        self.held = name
        move_in_direction([0, 0, 1], self.lift_height)

    def place_behind_door(self, door):
        move_to_pose(parse_place_pose(object_name=self.held, receptacle_name=door))
        open_gripper()
        detach_object(self.held)
        self.held = None


robot = Robot()
robot.look()
door_angle = robot.open_door('cabinet.handle_0', 'cabinet.door_0', target_angle=90)
if door_angle < 40:
    raise CompartmentError('the door opened only %.0f degrees, 40 are needed to place inside' % door_angle)
robot.pick_level('blue_box')
robot.place_behind_door('cabinet.door_0')
