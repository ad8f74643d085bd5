# Task: put the blue mug on the blue plate.
# Plan:
# 1. Look at the scene.
# 2. Pick the blue mug with the adaptive grasp from above (by its rim or handle, as mugs may be wider than
#    the gripper opens), attach it and lift it.
# 3. Get a place pose on the blue plate (the plate stays where it is), move there, release, move up.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, lift_height=0.1):
        self.held = None
        self.lift_height = lift_height

    def look(self, names=None):
        detect_objects(object_list=names)

    def pick_mug(self, name):
        open_gripper()
        grasp(parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1]))
        close_gripper()
        attach_object(name)
        self.held = name
        move_in_direction([0, 0, 1], self.lift_height)

    def release(self):
        open_gripper()
        detach_object(self.held)
        self.held = None
        move_in_direction([0, 0, 1], self.lift_height)

    def place_onto(self, receptacle):
        move_to_pose(parse_place_pose(object_name=self.held, receptacle_name=receptacle))
        self.release()


robot = Robot()
robot.look(['blue_mug', 'blue_plate'])
robot.pick_mug('blue_mug')
robot.place_onto('blue_plate')
