# Task: open the top drawer of the cabinet and put the red cup into it.
# Plan:
# 1. Look at the scene. The top drawer is cabinet.drawer_0; its handle is cabinet.handle_0 (the top row).
# 2. Read the drawer's prismatic joint near its handle, grasp the handle horizontally, attach the drawer,
#    pull it out along the joint axis (as far as it opens, at most 25 cm), release the handle and back away.
# 3. Look again, since the drawer moved and will be measured anew for placing.
# 4. Pick the red cup from above (central grasp if narrow enough, else the adaptive grasp by its rim), lift it.
# 5. Place it into the open top drawer, release it and move up.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, max_grip_width=0.075, lift_height=0.1, max_pull=0.25):
        self.held = None
        self.max_grip_width = max_grip_width  # the fingers open 8 cm (Panda), keep a margin
        self.lift_height = lift_height
        self.max_pull = max_pull

    def look(self, names=None):
        detect_objects(object_list=names)

    def grasp_pose_for(self, name):
        bbox = get_3d_bbox(name)
        narrow_side = min(bbox[3] - bbox[0], bbox[4] - bbox[1])
        if narrow_side < self.max_grip_width:
            return parse_central_lift_grasp_pose(object_name=name, description='center')
        return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])

    def pick(self, name):
        open_gripper()
        grasp(self.grasp_pose_for(name))
        close_gripper()
        attach_object(name)
        self.held = name
        move_in_direction([0, 0, 1], self.lift_height)

    def release(self):
        open_gripper()
        detach_object(self.held)
        self.held = None
        move_in_direction([0, 0, 1], self.lift_height)

    def place_into(self, receptacle):
        move_to_pose(parse_place_pose(object_name=self.held, receptacle_name=receptacle))
        self.release()

    def hold_handle(self, handle, part):
        open_gripper()
        grasp(parse_horizontal_grasp_pose(object_name=handle))
        close_gripper()
        attach_object(part)
        self.held = part

    def open_drawer(self, handle, drawer):
        joint = get_object_joint_info(object_name=drawer, position=get_object_center_position(handle), type='prismatic')
        distance = min(joint['joint_upper'] - joint['joint_value'] - 0.01, self.max_pull)
        if distance > 0.01:
            self.hold_handle(handle, drawer)
            move_in_direction(joint['joint_axis'], distance)
            open_gripper()
            detach_object(drawer)
            self.held = None
            move_in_direction(joint['joint_axis'], 0.05)
        # The drawer moved: measure it anew before placing into it.
        self.look()


robot = Robot()
robot.look()
robot.open_drawer('cabinet.handle_0', 'cabinet.drawer_0')
robot.pick('red_cup')
robot.place_into('cabinet.drawer_0')
