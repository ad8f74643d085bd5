# Task: sort the objects on the table by colour: put the green objects into the green bowl.
# Plan:
# 1. Look at the scene.
# 2. The green objects are the names starting with 'green_', leaving out the green bowl itself, other receptacles
#    that stay put, the table and the cabinet parts: here the green block.
# 3. For each: pick it (mugs with the adaptive grasp from above; others with a top-down central grasp if narrower
#    than the gripper opens, else the adaptive grasp from above), lift it, place it into the green bowl, release,
#    move up.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, max_grip_width=0.075, lift_height=0.1):
        self.held = None
        self.max_grip_width = max_grip_width  # the fingers open 8 cm (Panda), keep a margin
        self.lift_height = lift_height

    def look(self, names=None):
        detect_objects(object_list=names)

    def objects_of_colour(self, colour, receptacle):
        stays = ('basket', 'plate', 'bowl', 'saucer')
        return [n for n in get_object_name_list()
                if n.startswith(colour + '_') and n != receptacle and not n.startswith('cabinet')
                and not any(k in n for k in stays)]

    def grasp_pose_for(self, name):
        if 'mug' in name:
            return parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
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
robot.look()
for name in robot.objects_of_colour('green', 'green_bowl'):
    robot.pick(name)
    robot.place_into('green_bowl')
