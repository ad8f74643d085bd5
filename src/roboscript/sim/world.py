"""Builds a MuJoCo simulation from a :class:`WorldSpec` and a robot, with MjSpec.

The result, :class:`SimWorld`, owns the model and data and an index of named entities (objects, furniture parts,
the table, the robot) that ground truth, segmentation and the backend use.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Literal

import mujoco
import numpy as np

from roboscript.errors import UnknownNameError, did_you_mean
from roboscript.geometry import Transform, quat_from_yaw, quat_to_mujoco
from roboscript.kept import Kept
from roboscript.names import kind_of
from roboscript.objects import ObjectType
from roboscript.robots import ROBOT_PREFIX, RobotDescription, get_robot
from roboscript.robots.mujoco_model import RobotBinding, attach_robot, configure_options, is_descendant
from roboscript.sim.cameras import add_camera
from roboscript.sim.furniture import add_cabinet, add_table, drawer_interior
from roboscript.sim.world_file import ROBOT_BASE_XY, ObjectPlacement, WorldFileError, WorldSpec

EntityKind = Literal["object", "furniture", "part", "table", "robot"]


@dataclass(frozen=True)
class Entity:
    """A named thing in the world. ``bodies`` are the bodies whose geoms make up its shape."""

    index: int
    name: str
    kind: EntityKind
    bodies: tuple[int, ...]
    category: str = ""
    color: str = ""
    joint: int = -1  # the part's own joint (drawers, doors), -1 if none
    object_type: ObjectType | None = None


@dataclass
class SimWorld:
    """A compiled world: MuJoCo model and data, the entity index and the robot binding."""

    spec: WorldSpec
    model: mujoco.MjModel
    data: mujoco.MjData
    entities: list[Entity]
    robot: RobotBinding
    geom_entity: np.ndarray  # entity index of each geom, -1 if none
    _by_name: dict[str, Entity] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        self._by_name = {e.name: e for e in self.entities}

    def entity(self, name: str) -> Entity:
        """The entity ``name``; raises ``KeyError`` suggesting the closest names."""
        try:
            return self._by_name[name]
        except KeyError:
            close = did_you_mean(name, self._by_name, cutoff=0.4)
            hint = f"; {close}" if close else ""
            raise UnknownNameError(f"no object named {name!r} in world {self.spec.name!r}{hint}") from None

    def entity_names(self, kinds: tuple[EntityKind, ...] = ("object", "furniture", "part")) -> list[str]:
        return [e.name for e in self.entities if e.kind in kinds]


def _support_height(
    placed: dict[str, tuple[np.ndarray, float, ObjectPlacement]], placement: ObjectPlacement
) -> tuple[np.ndarray, float]:
    """World position of the object's bottom-centre and its yaw, for objects resting on other objects."""
    base_pos, base_yaw, base = placed[placement.support]
    c, s = math.cos(base_yaw), math.sin(base_yaw)
    dx, dy = placement.position[:2]
    if base.type.container and base.type.interior is not None:
        surface = base.type.interior[0][2]
    else:
        surface = base.type.bounds[1][2]
    offset = np.array([c * dx - s * dy, s * dx + c * dy, surface + 0.002])
    return base_pos + offset, base_yaw + placement.yaw


def _add_object(spec: mujoco.MjSpec, placement: ObjectPlacement, pos: np.ndarray, yaw: float) -> None:
    obj = placement.type
    quat = quat_to_mujoco(quat_from_yaw(yaw))
    body = spec.worldbody.add_body(name=placement.name, pos=list(pos), quat=list(quat))
    body.add_freejoint(name=f"{placement.name}/joint")
    # Torsional friction (condim 4) keeps grasped things from spinning; rolling friction (condim 6) lets round
    # fruit come to rest as real, slightly irregular fruit does.
    condim = 6 if obj.round else 4
    friction = [obj.friction, 0.01, 0.002 if obj.round else 0.0001]
    for k, part in enumerate(obj.parts):
        kind = getattr(mujoco.mjtGeom, f"mjGEOM_{part.kind.upper()}")
        size = list(part.size) + [0.0] * (3 - len(part.size))
        body.add_geom(
            name=f"{placement.name}/g{k}",
            type=kind,
            size=size,
            pos=list(part.pos),
            quat=list(quat_to_mujoco(np.array(part.quat))),
            rgba=list(part.rgba or obj.rgba),
            density=obj.density,
            condim=condim,
            friction=friction,
            solref=[0.004, 1.0],
        )


def _add_environment(spec: mujoco.MjSpec) -> None:
    spec.add_texture(
        name="floor_tex",
        type=mujoco.mjtTexture.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        rgb1=[0.32, 0.34, 0.36],
        rgb2=[0.26, 0.28, 0.3],
        width=256,
        height=256,
    )
    spec.add_material(name="floor_mat", texrepeat=[6, 6], reflectance=0.0, textures=["", "floor_tex"] + [""] * 8)
    spec.worldbody.add_geom(name="floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[4, 4, 0.1], material="floor_mat")
    spec.worldbody.add_light(
        name="key", pos=[0.5, -0.5, 3.0], dir=[-0.2, 0.2, -1.0], diffuse=[0.6, 0.6, 0.6], castshadow=False
    )
    spec.worldbody.add_light(
        name="fill", pos=[-1.0, 1.0, 3.0], dir=[0.3, -0.3, -1.0], diffuse=[0.35, 0.35, 0.35], castshadow=False
    )


def robot_mount(world: WorldSpec, description: RobotDescription) -> Transform:
    """Where the robot's base frame is: on the table at the conventional spot, turned by the robot's mount yaw."""
    return Transform(
        np.array([ROBOT_BASE_XY[0], ROBOT_BASE_XY[1], world.table.height]), quat_from_yaw(description.mount_yaw)
    )


def robot_joint_readings(world: SimWorld) -> Callable[[], dict[str, float]]:
    """The robot's joint readings by joint name (arm and gripper), as its encoders would give them."""
    model = world.model
    joints = [
        (model.joint(j).name, int(model.jnt_qposadr[j]))
        for j in range(model.njnt)
        if model.joint(j).name.startswith(ROBOT_PREFIX)
        and int(model.jnt_type[j]) in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
    ]
    return lambda: {name: float(world.data.qpos[adr]) for name, adr in joints}


COMPILED_WORLDS_KEPT = 8  # worlds (a layout of furniture and objects, a robot) a process keeps compiled


@dataclass(frozen=True)
class _Compiled:
    model: mujoco.MjModel  # objects wherever the first build of the world put them: moved by _placed
    drawer_frames: dict[str, tuple[np.ndarray, np.ndarray, tuple[np.ndarray, np.ndarray]]]


_compiled: Kept[_Compiled] = Kept(COMPILED_WORLDS_KEPT)


def build_world(world: WorldSpec, robot: str | None = None) -> SimWorld:
    """Compiles ``world`` with ``robot`` (default: the world's own) into a ready-to-step :class:`SimWorld`.

    The robot is at its home configuration and every object at its listed pose; nothing has been stepped yet.
    The compiled model is kept for the process: another build of the same world with its objects elsewhere (a
    benchmark's next seed) copies it and moves the objects, rather than compiling again. Every build is made that
    way, so a world is the same whichever build of it came first."""
    description = get_robot(robot or world.robot)
    compiled = _compiled.get((_without_layout(world), description), lambda: _compile(world, description))
    model = _placed(copy.copy(compiled.model), _object_poses(world, compiled.drawer_frames))
    data = mujoco.MjData(model)
    binding = RobotBinding.bind(model, description)
    data.qpos[binding.qpos] = description.home_array()
    data.ctrl[binding.actuators] = description.home_array()
    data.ctrl[binding.gripper_actuator] = description.gripper.open_ctrl
    for joint, value in zip(description.gripper.joints, description.gripper.open_qpos, strict=True):
        data.qpos[model.joint(ROBOT_PREFIX + joint).qposadr[0]] = value
    for cabinet in world.cabinets:  # drawers and doors the world starts open
        for row, part in cabinet.row_parts():
            data.qpos[model.joint(f"{part}.joint").qposadr[0]] = row.open
    mujoco.mj_forward(model, data)
    entities, geom_entity = _index_entities(model, world, binding)
    return SimWorld(world, model, data, entities, binding, geom_entity)


def _without_layout(world: WorldSpec) -> WorldSpec:
    """``world`` with every object at the origin of its support, unturned, and every drawer and door shut: what its
    compiled model depends on."""
    closed = tuple(replace(c, rows=tuple(replace(r, open=0.0) for r in c.rows)) for c in world.cabinets)
    objects = tuple(replace(o, position=(0.0,) * len(o.position), yaw=0.0) for o in world.objects)
    return replace(world, objects=objects, cabinets=closed)


def _compile(world: WorldSpec, description: RobotDescription) -> _Compiled:
    spec = mujoco.MjSpec()
    spec.modelname = world.name
    configure_options(spec)
    _add_environment(spec)
    add_table(spec, world.table)

    excludes: list[tuple[str, str]] = []
    for cabinet in world.cabinets:
        excludes += add_cabinet(spec, cabinet, world.table.height)

    attach_robot(spec, description, robot_mount(world, description))

    # Drawers hold objects: their interiors need the compiled geometry, so compile the furniture first.
    drawer_frames = _drawer_frames(spec, world) if any(o.support_kind == "inside" for o in world.objects) else {}
    poses = _object_poses(world, drawer_frames)
    for o in world.objects:
        _add_object(spec, o, *poses[o.name])

    for a, b in excludes:
        spec.add_exclude(bodyname1=a, bodyname2=b)
    for camera in world.cameras:
        add_camera(spec, camera)
    spec.worldbody.add_camera(
        name="overview", pos=[1.35, -1.05, 1.95], xyaxes=[0.62, 0.78, 0, -0.38, 0.3, 0.87], fovy=50
    )

    try:
        model = spec.compile()
    except ValueError as exc:
        raise WorldFileError(world.source, "world", f"MuJoCo could not compile it: {exc}") from exc
    return _Compiled(model, drawer_frames)


def _object_poses(world: WorldSpec, drawer_frames: dict) -> dict[str, tuple[np.ndarray, float]]:
    """Each object's position (its frame's origin) and yaw in the world, from where it stands on its support."""
    placed: dict[str, tuple[np.ndarray, float, ObjectPlacement]] = {}
    for o in world.objects:
        if o.support_kind == "table":
            pos = np.array([o.position[0], o.position[1], world.table.height + 0.001])
            yaw = o.yaw
        elif o.support_kind == "on":
            pos, yaw = _support_height(placed, o)
        else:
            pos, yaw = _inside_drawer(world, drawer_frames[o.support], o)
        # The object's frame origin is its bottom centre, but part bounds may dip slightly below it.
        pos = pos - np.array([0.0, 0.0, min(0.0, float(o.type.bounds[0][2]))])
        placed[o.name] = (pos, yaw, o)
    return {name: (pos, yaw) for name, (pos, yaw, _) in placed.items()}


def _placed(model: mujoco.MjModel, poses: dict[str, tuple[np.ndarray, float]]) -> mujoco.MjModel:
    """``model`` with each object (a free body) at its pose, and the constants that depend on the initial
    configuration (the model's extent, which the renderer's clipping planes scale with, among them) set anew."""
    for name, (pos, yaw) in poses.items():
        body = model.body(name).id
        quat = np.asarray(quat_to_mujoco(quat_from_yaw(yaw)), dtype=float)
        mujoco.mju_normalize4(quat)
        adr = int(model.jnt_qposadr[model.body_jntadr[body]])
        model.body_pos[body], model.body_quat[body] = pos, quat
        model.qpos0[adr : adr + 3] = model.qpos_spring[adr : adr + 3] = pos
        model.qpos0[adr + 3 : adr + 7] = model.qpos_spring[adr + 3 : adr + 7] = quat
    mujoco.mj_setConst(model, mujoco.MjData(model))
    return model


def _drawer_frames(spec: mujoco.MjSpec, world: WorldSpec) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """World pose and interior box of every drawer: (position, rotation, (lower, upper) in the drawer frame)."""
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    frames = {}
    for cabinet in world.cabinets:
        for part in cabinet.part_names():
            if kind_of(part) == "drawer":
                body = data.body(part)
                frames[part] = (
                    body.xpos.copy(),
                    body.xmat.reshape(3, 3).copy(),
                    drawer_interior(model, part),
                )
    return frames


def _inside_drawer(world: WorldSpec, frame, o: ObjectPlacement) -> tuple[np.ndarray, float]:
    position, rotation, (lower, upper) = frame
    center = (lower + upper) / 2
    local = np.array([center[0] + o.position[0], center[1] + o.position[1], lower[2] + 0.002])
    obj_lower, obj_upper = o.type.bounds
    half = (obj_upper[:2] - obj_lower[:2]) / 2
    c, s = abs(math.cos(o.yaw)), abs(math.sin(o.yaw))
    half = np.array([c * half[0] + s * half[1], s * half[0] + c * half[1]])
    if np.any(local[:2] - half < lower[:2] - 1e-6) or np.any(local[:2] + half > upper[:2] + 1e-6):
        index = world.object_names().index(o.name)
        raise WorldFileError(
            world.source,
            f"objects[{index}] {o.name!r}",
            f"does not fit inside {o.support} at offset {list(o.position)}: the drawer's interior is "
            f"{(upper[0] - lower[0]):.3f} x {(upper[1] - lower[1]):.3f} m, the object "
            f"{2 * half[0]:.3f} x {2 * half[1]:.3f} m",
        )
    yaw = math.atan2(rotation[1, 0], rotation[0, 0]) + o.yaw
    return position + rotation @ local, yaw


def _index_entities(model: mujoco.MjModel, world: WorldSpec, binding: RobotBinding) -> tuple[list[Entity], np.ndarray]:
    entities: list[Entity] = []

    def add(name: str, kind: EntityKind, bodies: list[int], **kwargs) -> None:
        entities.append(Entity(len(entities), name, kind, tuple(bodies), **kwargs))

    add("table", "table", [model.body("table").id], category="table")
    for o in world.objects:
        add(
            o.name,
            "object",
            [model.body(o.name).id],
            category=o.type.category,
            color=o.type.color,
            object_type=o.type,
        )
    for cabinet in world.cabinets:
        root = model.body(cabinet.name).id
        subtree = [b for b in range(model.nbody) if is_descendant(model, b, root)]
        add(cabinet.name, "furniture", subtree, category="cabinet", color="white")
        for part in cabinet.part_names():
            body = model.body(part).id
            joint = model.body_jntadr[body] if model.body_jntnum[body] > 0 else -1
            category = part.split(".")[1].split("_")[0]
            add(
                part,
                "part",
                [body],
                category=category,
                color="white" if category != "handle" else "gray",
                joint=int(joint),
            )
    add("robot", "robot", sorted(binding.body_ids), category="robot")

    # Each geom belongs to the most specific entity whose own bodies hold it (a handle, not its drawer).
    geom_entity = np.full(model.ngeom, -1, dtype=np.int32)
    body_owner: dict[int, int] = {}
    for e in entities:
        for b in e.bodies:
            if b not in body_owner or e.kind in ("part", "object"):
                body_owner[b] = e.index
    for g in range(model.ngeom):
        geom_entity[g] = body_owner.get(int(model.geom_bodyid[g]), -1)
    return entities, geom_entity
