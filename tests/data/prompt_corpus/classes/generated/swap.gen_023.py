# Task: swap the positions of the green block and the lemon.
# Plan:
# 1. Look at the scene and remember where the green block and the lemon stand, before anything moves.
# 2. Pick the green block and set it aside on a free spot of the table (at least 15 cm away), so its place is free.
# 3. Pick the lemon and place it where the green block was.
# 4. Pick the green block again and place it where the lemon was.
#    Each pick uses a top-down central grasp if the object is narrower than the gripper opens, else the adaptive
#    grasp from above.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, max_grip_width=0.075, lift_height=0.1):
        self.held = None
        self.max_grip_width = max_grip_width  # the fingers open 8 cm (Panda), keep a margin
        self.lift_height = lift_height

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

    def set_aside(self):
        move_to_pose(parse_place_pose(object_name=self.held, receptacle_name='table'))
        self.release()

    def place_at(self, position):
        move_to_pose(parse_place_pose(object_name=self.held, position=[position[0], position[1], position[2]]))
        self.release()

    def swap(self, first, second):
        first_at = get_object_center_position(first)
        second_at = get_object_center_position(second)
        self.pick(first)
        self.set_aside()
        self.pick(second)
        self.place_at(first_at)
        self.pick(first)
        self.place_at(second_at)


robot = Robot()
robot.look()
robot.swap('green_block', 'lemon')
