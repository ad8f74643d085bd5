# Task: put the rubiks cube into the green bowl.
# Plan:
# 1. Look at the scene with the cameras.
# 2. Choose a grasp for the rubiks cube: a top-down central grasp if it is narrower than the gripper opens,
#    else the adaptive grasp from above; grasp it, attach it and lift it.
# 3. Get a place pose inside the green bowl (the bowl stays where it is), move there, release, move up.


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

    def place_into(self, receptacle):
        move_to_pose(parse_place_pose(object_name=self.held, receptacle_name=receptacle))
        self.release()


robot = Robot()
robot.look(['rubiks_cube', 'green_bowl'])
robot.pick('rubiks_cube')
robot.place_into('green_bowl')
