# Task: put the white porcelain mug next to the brown cup.
# Plan:
# 1. Look at the scene.
# 2. Work out two candidate spots beside the brown cup, to its left (+y) and to its right (-y): the cup's centre
#    moved sideways by half the cup's width, half the mug's width and a 3 cm gap.
# 3. Keep the candidate that lies on the table and is farthest from the other objects on it.
# 4. Pick the mug with the adaptive grasp from above (by its rim or handle), lift it.
# 5. Place it at the chosen spot, release it and move up.


class Robot:
    """The arm with its parallel gripper; remembers what it holds."""

    def __init__(self, lift_height=0.1, gap=0.03):
        self.held = None
        self.lift_height = lift_height
        self.gap = gap

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

    def place_at(self, position):
        move_to_pose(parse_place_pose(object_name=self.held, position=[position[0], position[1], position[2]]))
        self.release()

    def spot_next_to(self, obj, anchor):
        anchor_box = get_3d_bbox(anchor)
        obj_box = get_3d_bbox(obj)
        offset = (anchor_box[4] - anchor_box[1]) / 2 + (obj_box[4] - obj_box[1]) / 2 + self.gap
        center = get_object_center_position(anchor)
        candidates = [center + np.array([0, offset, 0]), center - np.array([0, offset, 0])]
        table = get_3d_bbox('table')
        others = [n for n in get_object_name_list()
                  if n not in ('table', obj, anchor) and not n.startswith('cabinet')]
        best, best_clearance = candidates[0], -1.0
        for spot in candidates:
            if not (table[0] < spot[0] < table[3] and table[1] < spot[1] < table[4]):
                continue
            clearance = min([np.linalg.norm(get_object_center_position(n)[:2] - spot[:2]) for n in others] + [10.0])
            if clearance > best_clearance:
                best, best_clearance = spot, clearance
        return best


robot = Robot()
robot.look()
target = robot.spot_next_to('white_porcelain_mug', 'brown_cup')
robot.pick_mug('white_porcelain_mug')
robot.place_at(target)
