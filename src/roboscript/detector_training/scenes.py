"""Training scenes for the perception detector: generated worlds, varied the way tasks leave them, rendered by every
camera with the simulator's segmentation as the labels.

A world of the ``detector_scenes`` recipe is varied before it is built (a thing stacked on another, a thing put
away in a drawer, a door row under the drawers) and after (the arm moved, drawers pulled and doors swung open,
what is in a drawer moving with it). Each variation is one :class:`SceneVariation` draw from the world's own seeded
stream, so a scene is reproducible from ``(seed, index)`` alone.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.generate.recipe import Recipe, load_recipe
from roboscript.generate.worlds import GenerationError, generate_world, world_seed
from roboscript.objects import object_types
from roboscript.perception.reconstruction.self_filter import SelfFilter
from roboscript.robot_io import CameraFrame
from roboscript.sim.world_file import WorldFileError, WorldSpec, parse_world

RECIPE = "detector_scenes"
ROBOTS = ("panda", "ur5e")
SCENE_STREAM = 7_919  # offsets the variation's random stream from the world's own


@dataclass(frozen=True)
class SceneVariation:
    """How often each variation is drawn; ``arm_spread`` is how far (radians) each arm joint strays from home."""

    door_row: float = 0.3
    stacked: float = 0.3
    in_drawer: float = 0.7
    drawer_open: float = 0.35
    filled_drawer_open: float = 0.8  # a drawer things were put in is pulled out this often
    against_cabinet: float = 0.5  # a thing stands against the cabinet's side this often
    door_open: float = 0.4
    arm_spread: float = 0.8
    poses: int = 3  # renders per world: home first, then the arm and the furniture moved (twice)


@dataclass(frozen=True)
class EntityLabel:
    """What a segmentation index stands for: ``kind`` as the world's entities say, ``type_name`` the object
    library's type for objects ('' otherwise)."""

    index: int
    name: str
    kind: str
    type_name: str = ""
    category: str = ""  # left empty: ground-truth boxes answer to the entity's name alone
    color: str = ""


@dataclass
class LabelledView:
    """One camera's frame of a training scene, with what its segmentation's indices stand for, and the robot's
    pixels as the self-filter tells them from the joint readings (as perception will at run time)."""

    frame: CameraFrame
    labels: dict[int, EntityLabel]
    spec: WorldSpec
    pose: int
    robot_mask: np.ndarray

    @property
    def world(self) -> str:
        return self.spec.name


def scene_world(recipe: Recipe, seed: int, index: int, variation: SceneVariation):
    """World ``index`` of the training run ``seed``, varied before it is built; its robot alternates."""
    generated = generate_world(recipe, seed, index, name=f"scene_{seed}_{index:04d}")
    rng = np.random.default_rng(np.random.SeedSequence([seed, index, SCENE_STREAM]))
    data = copy.deepcopy(generated.data)
    data["robot"] = ROBOTS[index % len(ROBOTS)]
    furniture = data.get("furniture", [])
    if furniture and rng.random() < variation.door_row:
        furniture[0]["rows"] = ["drawer", "drawer", "drawer", "door"]
    _maybe_stack(data, rng, variation.stacked)
    if furniture:
        _maybe_put_away(data, rng, variation.in_drawer)
    source = f"<training scene {seed}/{index}>"
    try:
        spec = parse_world(data, source)
    except WorldFileError:
        return generated.spec  # a variation that does not fit is left out
    if furniture and rng.random() < variation.against_cabinet:
        return _against_cabinet(data, spec, rng, source) or spec
    return spec


def _against_cabinet(data: dict, spec: WorldSpec, rng: np.random.Generator, source: str) -> WorldSpec | None:
    """The world with one thing on the table moved against the cabinet's side that faces the robot's middle, a few
    millimetres from it (the paper's basket stands so): which pixels are the thing's and which the cabinet's must
    then be told from more than a gap. None where the thing does not fit there."""
    cabinet = spec.cabinets[0]
    supports = {o.get("on") for o in data["objects"]} | {o.get("inside") for o in data["objects"]}
    free = [o for o in data["objects"] if "on" not in o and "inside" not in o and o["name"] not in supports]
    if not free:
        return None
    thing = free[int(rng.integers(len(free)))]
    radius = object_types()[thing["type"]].footprint_radius
    depth, width = cabinet.depth, cabinet.width
    x0, y0 = cabinet.position
    if depth / 2 - radius < 0:
        return None
    moved = copy.deepcopy(data)
    entry = next(o for o in moved["objects"] if o["name"] == thing["name"])
    entry["position"] = [
        float(x0 + rng.uniform(-1, 1) * (depth / 2 - radius)),
        float(y0 - width / 2 - radius - rng.uniform(0.003, 0.02)),
    ]
    try:
        return parse_world(moved, source)
    except WorldFileError:
        return None


def _pickable_on_table(data: dict) -> list[dict]:
    library = object_types()
    supports = {o.get("on") for o in data["objects"]}
    return [
        o for o in data["objects"]
        if library[o["type"]].pickable and "on" not in o and "inside" not in o and o["name"] not in supports
    ]  # fmt: skip


def _maybe_stack(data: dict, rng: np.random.Generator, chance: float) -> None:
    """One thing on another, as stacking tasks leave them: the lower one listed first."""
    free = _pickable_on_table(data)
    if len(free) < 2 or rng.random() >= chance:
        return
    lower, upper = (free[k] for k in rng.choice(len(free), 2, replace=False))
    data["objects"].remove(upper)
    data["objects"].append({"name": upper["name"], "type": upper["type"], "on": lower["name"],
                            "position": [0.0, 0.0], "yaw": upper.get("yaw", 0.0)})  # fmt: skip


def _maybe_put_away(data: dict, rng: np.random.Generator, chance: float) -> None:
    """One or two small things in one drawer, side by side: a robot's tasks leave things there, and perception must
    tell them from the drawer they lie in."""
    library = object_types()
    small = [o for o in _pickable_on_table(data) if library[o["type"]].size[2] < 0.1]
    if not small or rng.random() >= chance:
        return
    count = min(len(small), int(rng.integers(1, 3)))
    drawers = [k for k, row in enumerate(data["furniture"][0]["rows"]) if row == "drawer"]
    drawer = int(rng.choice(drawers))
    for k, index in enumerate(rng.choice(len(small), count, replace=False)):
        thing = small[int(index)]
        data["objects"].remove(thing)
        side = 0.0 if count == 1 else (-0.08 if k == 0 else 0.08)
        data["objects"].append({"name": thing["name"], "type": thing["type"], "inside": f"cabinet.drawer_{drawer}",
                                "position": [0.0, side], "yaw": thing.get("yaw", 0.0)})  # fmt: skip


def scene_views(
    seed: int, index: int, variation: SceneVariation | None = None, recipe: Recipe | None = None
) -> Iterator[LabelledView]:
    """Every camera's view of world ``index`` of run ``seed``, at each of its poses; nothing if the recipe fits no
    world for that seed."""
    variation = variation or SceneVariation()
    recipe = recipe or load_recipe(RECIPE)
    try:
        spec = scene_world(recipe, seed, index, variation)
    except GenerationError:
        return
    rng = world_seed(seed * 1_000_003 + SCENE_STREAM, index)
    try:
        views = list(world_views(spec, variation.poses, lambda backend: _move_things(backend, rng, variation)))
    except WorldFileError:  # a variation the simulator cannot build (things put away that do not fit together)
        views = list(world_views(generate_world(recipe, seed, index, name=spec.name).spec, variation.poses,
                                 lambda backend: _move_things(backend, rng, variation)))  # fmt: skip
    yield from views


def world_views(
    spec: WorldSpec, poses: int = 1, move: Callable[[MujocoBackend], None] | None = None
) -> Iterator[LabelledView]:
    """Every camera's view of the world ``spec`` once settled, and again after each call of ``move`` (``poses``
    views per camera in all)."""
    with MujocoBackend(spec, settle=0.6) as backend:
        labels = _labels(backend)
        robot = SelfFilter(backend.robot, backend.base_pose())
        for pose in range(poses):
            if pose and move is not None:
                move(backend)
            frames = [backend.capture(camera) for camera in backend.camera_names()]
            masks = robot.masks(frames, backend.joint_states())
            for frame, mask in zip(frames, masks, strict=True):
                yield LabelledView(frame, labels, spec, pose, mask)


def _labels(backend: MujocoBackend) -> dict[int, EntityLabel]:
    out = {}
    for e in backend.sim_world.entities:
        out[e.index] = EntityLabel(e.index, e.name, e.kind, e.object_type.name if e.object_type else "")
    return out


def _move_things(backend: MujocoBackend, rng: np.random.Generator, variation: SceneVariation) -> None:
    """The arm to a random pose near home, drawers pulled and doors swung at random (what a drawer holds moves
    with it); kinematics only: nothing is simulated, so nothing falls."""
    world = backend.sim_world
    model, data = world.model, world.data
    binding = world.robot
    home = np.asarray(backend.robot.home, dtype=float)
    q = np.clip(home + rng.uniform(-variation.arm_spread, variation.arm_spread, home.shape),
                binding.joint_lower, binding.joint_upper)  # fmt: skip
    data.qpos[binding.qpos] = q
    mujoco.mj_kinematics(model, data)
    before = {e.name: data.xpos[e.bodies[0]].copy() for e in world.entities if e.kind == "part" and e.joint >= 0}
    for e in world.entities:
        if e.kind != "part" or e.joint < 0:
            continue
        low, high = model.jnt_range[e.joint]
        chance = variation.drawer_open if ".drawer_" in e.name else variation.door_open
        if _inside(backend, e.name):
            chance = variation.filled_drawer_open
        if rng.random() < chance:
            data.qpos[model.jnt_qposadr[e.joint]] = rng.uniform(low + 0.3 * (high - low), high)
    mujoco.mj_kinematics(model, data)
    for e in world.entities:
        if e.name in before:
            shift = data.xpos[e.bodies[0]] - before[e.name]
            for thing in _inside(backend, e.name):
                adr = model.jnt_qposadr[model.body_jntadr[thing.bodies[0]]]
                data.qpos[adr : adr + 3] += shift
    mujoco.mj_forward(model, data)


def _inside(backend: MujocoBackend, drawer: str) -> list:
    spec = backend.sim_world.spec
    names = [o.name for o in spec.objects if o.support_kind == "inside" and o.support == drawer]
    return [backend.sim_world.entity(n) for n in names]
