"""Oracle programs: the text of a verified program for a template task, written against the tool API only.

A program is assembled from the helpers it needs (picking up, putting down, opening a drawer, finding a free spot
beside something) and the lines of its plan. The helpers do what a careful program does: a grasp that fits any
shape, a lift clear of the table before carrying, a retreat upward after letting go, a drawer's handle taken from
the side and pulled along the joint's axis.
"""

from __future__ import annotations

from dataclasses import dataclass, field

PICK = '''def pick(name):
    """Grasps `name` from above where its shape allows, and lifts it clear of what is around it."""
    open_gripper()
    grasp_pose = parse_adaptive_shape_grasp_pose(object_name=name, preferred_approach_direction=[0, 0, -1])
    grasp(grasp_pose)
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
'''

PUT = '''def put(name, place_pose):
    """Carries the held `name` to `place_pose`, lets go of it and moves the hand up and away."""
    move_to_pose(place_pose)
    open_gripper()
    detach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
'''

OPEN_DRAWER = '''def open_drawer(drawer, handle):
    """Pulls `drawer` open by its `handle`, along its joint's axis, and lets go of the handle."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='prismatic')
    axis = joint_info['joint_axis']
    move_in_direction(axis, distance=0.22)
    open_gripper()
    detach_object(drawer)
    move_in_direction(axis, distance=0.03)
'''

OPEN_DOOR = '''def open_door(door, handle):
    """Swings `door` open by its `handle`, along an arc about its hinge, and lets go of the handle."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(door)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='revolute')
    path = generate_arc_path_around_joint(current_pose=get_gripper_pose(), joint_axis=joint_info['joint_axis'],
                                          joint_position=joint_info['joint_position'], n=20, angle=70)
    follow_path(path)
    open_gripper()
    detach_object(door)
'''

CLOSE_DRAWER = '''def close_drawer(drawer, handle):
    """Pushes `drawer` shut by its `handle`, back along its joint's axis as far as it is open, and lets go."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=handle))
    close_gripper()
    attach_object(drawer)
    handle_position = get_object_center_position(handle)
    joint_info = get_object_joint_info(obj_name='cabinet', position=handle_position, type='prismatic')
    move_in_direction(joint_info['joint_axis'], distance=-joint_info['joint_value'])
    open_gripper()
    detach_object(drawer)
'''

PICK_FROM_SIDE = '''def pick_from_side(name):
    """Grasps `name` from the side, fingers level, and lifts it clear of what is around it."""
    open_gripper()
    grasp(parse_horizontal_grasp_pose(object_name=name))
    close_gripper()
    attach_object(name)
    move_in_direction(direction=[0, 0, 1], distance=0.1)
'''

SPOT_BESIDE = '''def spot_beside(target, name, obstacles):
    """A free place on the table right beside `target` for `name`: left, right, nearer or farther, the first
    side where `name` clears every obstacle and stays within the arm's comfortable reach."""
    box, mine = get_3d_bbox(target), get_3d_bbox(name)
    center, half = (box[:2] + box[3:5]) / 2, (mine[3:5] - mine[:2]) / 2
    others = [get_3d_bbox(o) for o in obstacles]
    for side in ([0, 1], [0, -1], [-1, 0], [1, 0]):
        side = np.array(side, dtype=float)
        spot = center + side * ((box[3:5] - box[:2]) / 2 + half + 0.03)
        low, high = spot - half - 0.015, spot + half + 0.015
        if any(low[0] < o[3] and o[0] < high[0] and low[1] < o[4] and o[1] < high[1] for o in others):
            continue
        if 0.3 < np.linalg.norm(spot - np.array([-0.45, 0.0])) < 0.7:
            return np.array([spot[0], spot[1], mine[2]])
    raise ValueError(f'no free spot beside {target} for {name}')
'''


@dataclass
class Program:
    """A program being written: its task line, its plan, the helpers it uses and its body."""

    instruction: str
    plan: list[str] = field(default_factory=list)
    helpers: list[str] = field(default_factory=list)
    body: list[str] = field(default_factory=list)

    def use(self, *helpers: str) -> Program:
        for helper in helpers:
            if helper not in self.helpers:
                self.helpers.append(helper)
        return self

    def step(self, plan: str, *lines: str) -> Program:
        """One step of the plan (a comment line) and the code that does it."""
        self.plan.append(plan)
        self.body.extend(lines)
        return self

    def text(self) -> str:
        head = [f"# Task: {self.instruction}", "# Plan:"]
        head += [f"# {i}. {line}" for i, line in enumerate(self.plan, 1)]
        top = "\n".join(head) + "\n" + "detect_objects()"
        parts = [top, *(h.rstrip("\n") for h in self.helpers), "\n".join(self.body)]
        return "\n\n\n".join(parts) + "\n"


def move_into(program: Program, name: str, receptacle: str, onto: bool = False) -> Program:
    """Picks ``name`` and puts it into ``receptacle`` (a container or an open drawer), or ``onto`` it (a plate)."""
    return program.use(PICK, PUT).step(
        f"Pick up the {words(name)} and put it {'onto' if onto else 'into'} the {words(receptacle)}.",
        f"pick({name!r})",
        f"put({name!r}, parse_place_pose(object_name={name!r}, receptacle_name={receptacle!r}))",
    )


def move_to(program: Program, name: str, position: str, why: str) -> Program:
    """Picks ``name`` and puts it at ``position``, a Python expression of the program's (a variable)."""
    return program.use(PICK, PUT).step(
        why,
        f"pick({name!r})",
        f"put({name!r}, parse_place_pose(object_name={name!r}, position={position}))",
    )


def words(name: str) -> str:
    """A name in words: ``cabinet.drawer_1`` is the cabinet's drawer 1, ``white_bowl`` the white bowl."""
    return name.replace(".", "'s ").replace("_", " ")
