"""A planning scene from what the cameras saw: the robot's own model, each known object as a movable body of
occupancy boxes (so it can be carried), and every other observed surface as fixed occupancy boxes named after the
furniture part it lies on (so a gripper may be let touch a drawer it pulls), or ``scene``. A drawer or door whose
joint perception estimated turns or slides on that joint, its handle with it: a screen of a door's swing sees the door
sweep toward the arm, as in the ground-truth scene.

Nothing here reads the simulator's geometry: the input is points. :class:`PerceivedSceneSource` rebuilds the
scene from a :class:`~roboscript.perception.base.Perception` whenever the robot let something go or perception
looked again, which is when what was seen may have moved.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import mujoco
import numpy as np

from roboscript.geometry import Box3D, Transform
from roboscript.perception.base import ArticulationJoint, Perception, joints_if_known, outside, within
from roboscript.perception.furniture.articulation import part_motion
from roboscript.perception.furniture.carcass import carcass_facing, carcass_panels
from roboscript.perception.reconstruction.carving import SHELL, seen_through
from roboscript.perception.reconstruction.memory import remembered
from roboscript.phases import timed
from roboscript.planning.occupancy import VOXEL, RememberedBoxes, occupied_boxes, unique_cells
from roboscript.planning.scene import PlanningScene
from roboscript.robots.description import RobotDescription
from roboscript.robots.mujoco_model import RobotBinding, attach_robot, configure_options

OBJECT_VOXEL = 0.01  # metres: objects are small and are reached into, so their boxes are finer
UNKNOWN = "scene"  # the name of observed surfaces that belong to no known object or part
OBJECT_MARGIN = 0.01  # metres around an object's box whose points are taken to be its own
PART_MARGIN = 0.01  # metres around a part's box whose points are taken to be its own
SUPPORT_BAND = 0.002  # metres above an object's underside within which points are what it stands on
REACH = 1.2  # metres from the robot's base beyond which surfaces are no obstacle (either arm reaches < 1 m)
BELOW_BASE = 0.05  # metres below the robot's base (the table it stands on) beyond which surfaces are no obstacle


@dataclass(frozen=True)
class SceneContents:
    """Observed points sorted by what they belong to: ``objects`` move (and may be carried), ``fixed`` do not,
    but for the parts ``joints`` names: by part (a drawer, a door, a handle), the joint it moves on."""

    objects: Mapping[str, np.ndarray]
    fixed: Mapping[str, np.ndarray]
    joints: Mapping[str, ArticulationJoint] = field(default_factory=dict)


def build_perceived_scene(
    description: RobotDescription,
    mount: Transform,
    contents: SceneContents,
    padding: float = 0.005,
    boxes_of: Callable[[np.ndarray, float], list] = occupied_boxes,
) -> PlanningScene:
    """A :class:`PlanningScene` of the robot at ``mount`` and occupancy boxes of ``contents`` (made by ``boxes_of``,
    points and voxel size -> boxes, as :func:`occupied_boxes`). Every name in ``contents`` is a body of the scene,
    even with no points, so tools may allow or forbid contacts with it."""
    spec = mujoco.MjSpec()
    spec.modelname = "perceived"
    configure_options(spec)
    attach_robot(spec, description, mount, visual=False)
    moving: dict[str, mujoco.MjsBody] = {}  # by moving part, the body that carries its joint
    for name, points in contents.fixed.items():
        joint = contents.joints.get(name)
        if joint is None:
            body = spec.worldbody.add_body(name=f"fixed/{name}")
            _add_boxes(body, boxes_of(points, VOXEL), np.zeros(3))
            continue
        if joint.part not in moving:
            moving[joint.part] = _jointed_body(spec, joint)
        carrier = moving[joint.part]
        body = carrier if name == joint.part else carrier.add_body(name=f"part/{name}")
        _add_boxes(body, boxes_of(points, VOXEL), np.asarray(joint.position, dtype=float))
    for name, points in contents.objects.items():
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        origin = points.mean(axis=0) if len(points) else np.zeros(3)
        body = spec.worldbody.add_body(name=f"object/{name}", pos=list(origin))
        body.add_freejoint()
        # Planning never steps this model; a fixed mass spares bodies with no points MuJoCo's mass check.
        body.mass, body.inertia, body.explicitinertial = 0.1, [1e-4, 1e-4, 1e-4], True
        _add_boxes(body, boxes_of(points, OBJECT_VOXEL), origin)
    model = spec.compile()
    labels = []
    for b in range(model.nbody):
        name = model.body(b).name
        labels.append(name.split("/", 1)[1] if name.startswith(("fixed/", "object/", "part/")) else name)
    objects = {name: model.body(f"object/{name}").id for name in contents.objects}
    return PlanningScene(model, RobotBinding.bind(model, description), labels, objects, padding)


def _jointed_body(spec: mujoco.MjSpec, joint: ArticulationJoint) -> mujoco.MjsBody:
    """A body for ``joint.part`` with its origin on the joint's axis, turning or sliding on it from where it was
    seen (a joint value of 0)."""
    body = spec.worldbody.add_body(name=f"part/{joint.part}", pos=list(np.asarray(joint.position, dtype=float)))
    kind = mujoco.mjtJoint.mjJNT_HINGE if joint.type == "revolute" else mujoco.mjtJoint.mjJNT_SLIDE
    body.add_joint(name=f"part/{joint.part}", type=kind, axis=list(np.asarray(joint.axis, dtype=float)))
    body.mass, body.inertia, body.explicitinertial = 0.1, [1e-4, 1e-4, 1e-4], True
    return body


def _add_boxes(body, boxes, origin: np.ndarray) -> None:
    for box in boxes:
        body.add_geom(
            type=mujoco.mjtGeom.mjGEOM_BOX,
            pos=list(box.center - origin),
            size=list(np.maximum(box.half_size, 1e-4)),
            contype=1,
            conaffinity=1,
            group=3,
        )


def sort_points(
    scene_points: np.ndarray,
    objects: Mapping[str, np.ndarray],
    object_boxes: Mapping[str, Box3D],
    parts: Mapping[str, Box3D],
) -> SceneContents:
    """Observed points sorted for :func:`build_perceived_scene`: each object keeps its own points, and surfaces
    near an object's box are left out of the fixed ones (they are its unclaimed edges, and a hand reaching for it
    must not find them in the way). The rest goes to the smallest part box it lies in, else to ``scene``.

    Points under an object's box are kept: the table it stands on stays whole under it."""
    rest = np.asarray(scene_points, dtype=float).reshape(-1, 3)
    for box in object_boxes.values():
        # Grown by the margin on every side but the bottom, which rises to just above what it stands on.
        lower = np.array([*box.lower[:2], box.lower[2] + SUPPORT_BAND + OBJECT_MARGIN])
        rest = outside(rest, Box3D(lower, box.upper), OBJECT_MARGIN)
    fixed: dict[str, np.ndarray] = {name: np.zeros((0, 3)) for name in parts}
    owner = np.full(len(rest), -1)
    smallest = np.full(len(rest), np.inf)
    names = list(parts)
    for k, name in enumerate(names):
        box = parts[name]
        inside = within(rest, box, PART_MARGIN)
        better = inside & (box.volume < smallest)
        owner[better], smallest[better] = k, box.volume
    for k, name in enumerate(names):
        fixed[name] = rest[owner == k]
    fixed[UNKNOWN] = rest[owner == -1]
    return SceneContents(dict(objects), fixed)


def filled_below(
    points: np.ndarray,
    floor: float,
    step: float = OBJECT_VOXEL / 2,
    seen_free: Callable[[np.ndarray], np.ndarray] | None = None,
) -> np.ndarray:
    """``points`` with each column of them filled down to ``floor``: an object resting on something is solid
    under the surfaces seen from above (its sides and underside are often out of every camera's sight, and a
    finger must not pass under a banana's seen top). A bowl's inside is filled only below its seen bottom.
    ``seen_free`` (fill points -> mask) tells the fill a camera saw through, which is left out more than
    :data:`~roboscript.perception.reconstruction.carving.SHELL` below the column's lowest seen point (the gap under a
    footed bowl's rim: :mod:`roboscript.perception.reconstruction.carving`)."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    if len(points) == 0:
        return points
    columns = np.floor(points[:, :2] / step).astype(np.int64)
    keys, inverse = unique_cells(columns)
    lowest = np.full(len(keys), np.inf)
    np.minimum.at(lowest, inverse, points[:, 2])
    # Each column's fill is np.arange(floor, lowest, step), made for all columns at once.
    counts = np.maximum(np.ceil((lowest - floor) / step), 0).astype(np.int64)
    if counts.sum() == 0:
        return points
    column = np.repeat(np.arange(len(keys)), counts)
    level = np.arange(len(column)) - np.repeat(np.cumsum(counts) - counts, counts)
    heights = floor + level * step
    xy = (keys[column] + 0.5) * step
    filled = np.column_stack([xy, heights])
    depth_below = lowest[column] - heights
    if seen_free is not None:
        deep = depth_below > SHELL
        if deep.any():
            drop = np.zeros(len(filled), dtype=bool)
            drop[deep] = seen_free(filled[deep])
            filled = filled[~drop]
    return np.vstack([points, filled])


def carcasses(perception: Perception) -> dict[str, np.ndarray]:
    """By furniture name, points filling its carcass's side and back panels
    (:mod:`roboscript.perception.furniture.carcass`) for each piece of furniture whose front could be told."""
    out = {}
    for name in perception.furniture():
        if "." in name:  # a part (drawer, door, handle): its furniture's carcass holds it
            continue
        facing = carcass_facing(perception, name)
        if facing is not None:
            seen = perception.points(name)
            out[name] = carcass_panels(seen.points, seen.normals, facing)
    return out


def moving_parts(perception: Perception) -> dict[str, ArticulationJoint]:
    """By furniture part (a drawer, a door, a handle), the joint it moves on, for those whose joint perception can
    tell now (a part whose front or handle was not seen well enough stays fixed)."""
    out = {}
    for name in perception.furniture():
        if "." not in name:  # the furniture itself: it does not move
            continue
        joints = joints_if_known(perception, name)
        if len(joints) == 1:
            out[name] = joints[0]
    return out


def within_reach(points: np.ndarray, mount: Transform) -> np.ndarray:
    """The points the arm mounted at ``mount`` could touch: within :data:`REACH` of its base and not below the
    surface it stands on (the floor, far walls and the table's legs are out of its reach)."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    near = np.linalg.norm(points - mount.position, axis=1) < REACH
    return points[near & (points[:, 2] > mount.position[2] - BELOW_BASE)]


class PerceivedSceneSource:
    """Keeps a planning scene built from ``perception`` up to date.

    ``robot_state`` gives the robot's joint readings by the joint's name in the robot's model (the arm's and the
    gripper's: proprioception, as :meth:`Backend.joint_states` reads it). Surfaces seen in earlier looks that the
    robot's body (perception's :meth:`~roboscript.perception.base.Perception.last_masks`) now hides are remembered
    (:mod:`roboscript.perception.reconstruction.memory`). :meth:`current` rebuilds
    the scene when :meth:`mark_stale` was called or perception has looked again since the last build.
    """

    def __init__(
        self,
        perception: Perception,
        description: RobotDescription,
        mount: Transform,
        robot_state: Callable[[], Mapping[str, float]],
        padding: float = 0.005,
    ):
        self.perception, self.description, self.mount = perception, description, mount
        self.robot_state, self.padding = robot_state, padding
        self._memory: dict[str, np.ndarray] = {}  # the fixed surfaces the last scene was built from, by owner
        self._joints: Mapping[str, ArticulationJoint] = {}  # the moving parts' joints the last scene was built with
        self.builds = 0
        self._boxes = RememberedBoxes()
        self._scene: PlanningScene | None = None
        self._looks = -1
        self._stale = True

    def mark_stale(self, moved: Mapping[str, tuple[np.ndarray, np.ndarray]] | None = None) -> None:
        """What was seen may have moved (the robot let go of something, or moved a part): rebuild before use.
        ``moved``: parts the hand moved, with where the TCP took hold and let go; their surfaces as seen before
        are remembered where that moved them on the joint the last scene gave them (:func:`part_motion`), and
        forgotten where it gave them none. Remembered where they were, a drawer's front pushed shut closed round
        the arm still at it; forgotten, a door's handle that the hand hid as it let go was free space, and the
        fingers coming back for it hooked it and swung the door (generated into_cupboard.gen_090)."""
        self._stale = True
        for name, (hand_from, hand_to) in (moved or {}).items():
            joint = self._joints.get(name)
            if joint is None:
                self._memory.pop(name, None)
            elif name in self._memory:
                self._memory[name] = part_motion(joint, hand_from, hand_to).apply(self._memory[name])

    @timed("scene")
    def current(self) -> PlanningScene:
        looks = getattr(self.perception, "looks", 0)
        if self._scene is None or self._stale or looks != self._looks:
            with self.perception.without_looking():
                contents = self.contents()
            self._scene = build_perceived_scene(self.description, self.mount, contents, self.padding, self._boxes.boxes)
            self._boxes.next_scene()
            self._looks, self._stale = getattr(self.perception, "looks", 0), False
            self.builds += 1
        return self._scene

    def contents(self) -> SceneContents:
        perception = self.perception
        objects = perception.objects()
        scene_points = within_reach(perception.scene_points(), self.mount)
        frames = perception.last_frames()
        hidden = perception.last_masks() if frames else []
        if frames and self._memory:
            scene_points = np.vstack([scene_points, remembered(np.vstack(list(self._memory.values())), frames, hidden)])
        object_boxes = {name: perception.box(name) for name in objects}
        object_points = {name: self._filled(name, object_boxes[name], frames, hidden) for name in objects}
        parts = {name: perception.box(name) for name in perception.furniture()}
        contents = sort_points(scene_points, object_points, object_boxes, parts)
        # Only fixed surfaces are remembered: an object's are where it was, and it may be carried off.
        self._memory = {name: points for name, points in contents.fixed.items() if len(points)}
        fixed = dict(contents.fixed)
        for name, panels in carcasses(perception).items():
            fixed[name] = np.vstack([fixed.get(name, np.zeros((0, 3))), within_reach(panels, self.mount)])
        self._joints = moving_parts(perception)
        return SceneContents(contents.objects, fixed, self._joints)

    def _filled(self, name: str, box: Box3D, frames: list, hidden: list) -> np.ndarray:
        """An object's seen points filled down to its underside, less the fill the last look's views (``hidden``:
        their robot pixels) saw through."""
        surface = self.perception.points(name).points

        def seen_free(fill: np.ndarray) -> np.ndarray:
            return seen_through(fill, surface, frames, hidden)

        return filled_below(surface, float(box.lower[2]), seen_free=seen_free if frames else None)

    def state(self) -> np.ndarray:
        """The scene's ``qpos``: objects where they were seen, the robot's joints as read."""
        scene = self._scene or self.current()  # the scene the planner has: it asked for it just before
        qpos = scene.model.qpos0.copy()
        readings = self.robot_state()
        for name, value in readings.items():
            joint = scene.model.joint(self.description.qualified(name))
            qpos[joint.qposadr[0]] = value
        return qpos
