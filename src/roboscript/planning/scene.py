"""The planning scene: the robot, static obstacles, objects as collision geometry, and attached objects.

The scene keeps its own copy of a compiled world model, so collision queries never disturb the simulation. Only
pairs that involve the robot (or an object it holds) are tested: MuJoCo's contype/conaffinity bits are set so that
robot geoms collide with everything, and the rest of the world does not collide with itself (objects resting on
the table are not a planning problem). Contacts closer than ``padding`` count as collisions.

:mod:`roboscript.planning.ground_truth_scene` copies the simulated geometry (ground truth) and :meth:`update` copies
its state; :mod:`roboscript.planning.perceived_scene` builds a model of the same form from observed surfaces.
"""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import itertools
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.geometry import Transform, turns_about
from roboscript.phases import timed
from roboscript.robots.description import RobotDescription
from roboscript.robots.mujoco_model import RobotBinding, is_descendant

REGRASP_LIMIT = 0.05  # metres a held object may have shifted in the hand and still be where the scene holds it
LEAVING_TOLERANCE = 0.002  # metres a contact being left may go deeper than it started (or than touching)
WORKSPACE_MARGIN = 0.02  # metres the arm's links keep inside a workspace box: a timed trajectory between two
# checked configurations, and the backend's own check, must not find a link just outside it
WORKSPACE = "workspace box"  # what a link leaving the box is reported in collision with

# contype/conaffinity bits. Two geoms collide if the type of either shares a bit with the affinity of the other.
# Moving arm links collide with everything; the environment only with the robot and held objects (objects resting on
# the table are no planning problem); the fixed base not with the table it stands on; the first moving link not with
# the base it turns on (MuJoCo's parent-child filter skips bodies welded to the world); the gripper's parts not with
# each other (its linkage touches itself); a held object not with the gripper holding it.
_ARM, _ENV, _BASE, _FIRST, _GRIPPER, _HELD = 1, 2, 4, 8, 16, 32
_BITS = {
    "arm": (_ARM, _ARM | _ENV | _BASE),
    "env": (_ENV, _ARM),
    "base": (_BASE, _ARM),
    "first_link": (_FIRST, _ARM | _ENV),
    "gripper": (_GRIPPER, _ARM | _ENV | _BASE | _FIRST),
    "held": (_HELD, _ARM | _ENV | _BASE | _FIRST),
}


@dataclass(frozen=True)
class Attachment:
    """An object held by the gripper: its pose relative to the TCP, and contacts allowed until it leaves them."""

    name: str
    body: int
    tcp_to_object: np.ndarray  # 4x4
    qpos_address: int  # where the object's free joint keeps its pose in qpos


@dataclass(frozen=True)
class _FollowedPart:
    """A drawer or door moving with the hand (:meth:`PlanningScene.part_following`): its joint's qpos address and
    value at the start, whether it turns, its axis's anchor and direction, and where the TCP started."""

    address: int
    start: float
    revolute: bool
    anchor: np.ndarray
    axis: np.ndarray
    tcp_start: np.ndarray


class PlanningScene:
    """Collision queries for arm configurations against the world, with attached objects and allowed pairs."""

    def __init__(
        self,
        model: mujoco.MjModel,
        robot: RobotBinding,
        body_labels: list[str],
        object_bodies: dict[str, int],
        padding: float = 0.005,
        pad_bodies_of_several_geoms: bool = True,
    ):
        """``pad_bodies_of_several_geoms``: whether the padding also holds between two bodies of several geoms each
        (see :meth:`_sync_body_margins`); a scene of observed boxes leaves it off (see
        :func:`roboscript.planning.perceived_scene.build_perceived_scene`)."""
        if padding < 0:
            raise ValueError(f"padding must be >= 0 metres, got {padding}")
        self._pad_bodies = pad_bodies_of_several_geoms
        self.model = model
        self.data = mujoco.MjData(model)
        self.robot = robot
        self.padding = padding
        self.body_labels = body_labels
        self.object_bodies = object_bodies
        self._qpos = robot.qpos
        # Queries call mj_kinematics and mj_collision directly; sleeping would make them skip bodies.
        model.opt.enableflags &= ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)

        nbody = model.nbody
        self._is_robot = np.zeros(nbody, dtype=bool)
        self._is_robot[list(robot.body_ids)] = True
        tcp_body = model.site_bodyid[robot.tcp_site]
        self._gripper_bodies = np.array([b for b in robot.body_ids if is_descendant(model, b, tcp_body)])
        # The last arm joint's body and all it carries: the TCP's pose alone places them.
        wrist = model.dof_bodyid[robot.dof[-1]]
        self._placed_by_tcp = np.array([is_descendant(model, b, wrist) for b in range(model.nbody)])
        self._collides = (model.geom_contype | model.geom_conaffinity) > 0
        moved = np.array([_moved_by_arm(model, b, robot) for b in range(nbody)])
        base = self._is_robot & ~moved
        first_link = self._is_robot & moved & base[model.body_parentid]
        gripper = np.zeros(nbody, dtype=bool)
        gripper[self._gripper_bodies] = True
        self._set_bits(~self._is_robot, "env", 0.0)
        # The floor is out of the arm's reach (the table is in the way) and a plane is tested against every geom.
        planes = (model.geom_type == mujoco.mjtGeom.mjGEOM_PLANE) & (model.geom_bodyid == 0)
        model.geom_contype[planes], model.geom_conaffinity[planes] = 0, 0
        self._set_bits(self._is_robot & moved & ~first_link & ~gripper, "arm", padding)
        self._set_bits(base, "base", 0.0)
        # The first link only turns about the base's axis, and it may be mounted closer to the table than the
        # padding (a UR5e's shoulder, 3 mm): with the padding it would collide in every configuration.
        self._set_bits(first_link, "first_link", 0.0)
        self._set_bits(gripper, "gripper", padding)

        self._allowed = np.zeros((nbody, nbody), dtype=bool)
        # Contacts that may be left but not deepened: body pair -> the least distance allowed (the start's).
        self._leaving: dict[tuple[int, int], float] = {}
        self._attached: dict[str, Attachment] = {}
        self._following: _FollowedPart | None = None
        self._attached_allowed: dict[str, set[int]] = {}
        self._lower, self._upper = robot.joint_lower - 1e-9, robot.joint_upper + 1e-9
        self._finger_qpos, self._finger_open = _open_finger_positions(model, robot, self._gripper_bodies)
        self._moving_bodies = np.flatnonzero(self._is_robot & moved)  # the base stays where it is mounted
        self._workspace: tuple[np.ndarray, np.ndarray] | None = None
        self._tcp = np.eye(4)  # the TCP's pose while placing held objects, kept to spare an allocation a query

    # --- state -----------------------------------------------------------------------------------------------

    def keep_inside(self, lower: np.ndarray, upper: np.ndarray, margin: float = WORKSPACE_MARGIN) -> None:
        """Makes configurations that put the origin of any moving link of the robot outside the box ``lower`` ..
        ``upper`` (shrunk by ``margin``) invalid, as a real arm's safety limits would refuse them."""
        lower, upper = np.asarray(lower, dtype=float) + margin, np.asarray(upper, dtype=float) - margin
        if lower.shape != (3,) or upper.shape != (3,) or np.any(lower >= upper):
            raise ValueError(f"a workspace box needs lower < upper on x, y and z (after a {margin} m margin)")
        self._workspace = (lower, upper)

    def _links_outside(self) -> list[int]:
        """The robot's moving bodies whose origin is outside the workspace box (after :meth:`_place`)."""
        if self._workspace is None:
            return []
        points = self.data.xpos[self._moving_bodies]
        outside = np.any((points < self._workspace[0]) | (points > self._workspace[1]), axis=1)
        return self._moving_bodies[outside].tolist()

    @property
    def dof(self) -> int:
        return len(self._qpos)

    @property
    def joint_lower(self) -> np.ndarray:
        return self.robot.joint_lower

    @property
    def joint_upper(self) -> np.ndarray:
        return self.robot.joint_upper

    def update(self, qpos: np.ndarray, held_from_state: bool = False) -> None:
        """Takes the world's state (every joint: objects, drawers, doors, the arm) from a full ``qpos`` vector.

        Held objects follow the gripper, not ``qpos``; with ``held_from_state`` (a state read off the world itself,
        as in simulation), where each sits in the hand is taken from ``qpos`` first: a held object that turned a
        little between the fingers is planned with as it is. A contact allowed at attachment is withdrawn once the
        held object has left it.
        """
        qpos = np.asarray(qpos, dtype=float)
        if qpos.shape != (self.model.nq,):
            raise ValueError(f"qpos must have {self.model.nq} entries (the world's), got shape {qpos.shape}")
        self.data.qpos[:] = qpos
        if self._attached and held_from_state:
            self._regrasp(qpos)
        if self._attached:
            self._place(qpos[self._qpos])
            mujoco.mj_collision(self.model, self.data)
            touching = {b for pair in self._contact_bodies() for b in pair}
            for name, allowed in self._attached_allowed.items():
                body = self._attached[name].body
                for other in list(allowed):
                    if other not in touching:
                        allowed.discard(other)
                        self._allowed[body, other] = self._allowed[other, body] = False

    def _regrasp(self, qpos: np.ndarray) -> None:
        """Each attachment's pose relative to the TCP as ``qpos`` has the object and the arm, where the object has
        only shifted in the hand (less than :data:`REGRASP_LIMIT`): one that fell out is not carried along."""
        mujoco.mj_kinematics(self.model, self.data)
        site = self.robot.tcp_site
        tcp = Transform.from_rotation(self.data.site_xpos[site], self.data.site_xmat[site].reshape(3, 3))
        for name, attachment in self._attached.items():
            body = attachment.body
            pose = Transform.from_rotation(self.data.xpos[body], self.data.xmat[body].reshape(3, 3))
            in_hand = tcp.inverse().compose(pose).matrix()
            if np.linalg.norm(in_hand[:3, 3] - attachment.tcp_to_object[:3, 3]) < REGRASP_LIMIT:
                self._attached[name] = dataclasses.replace(attachment, tcp_to_object=in_hand)

    def arm_positions(self) -> np.ndarray:
        return self.data.qpos[self._qpos].copy()

    def within_limits(self, q: np.ndarray) -> bool:
        return bool(((q >= self._lower) & (q <= self._upper)).all())

    @property
    def moving_bodies(self) -> np.ndarray:
        """The robot's bodies that the arm's joints move (the base stays where it is mounted)."""
        return self._moving_bodies

    @property
    def held_bodies(self) -> list[int]:
        """The bodies of the objects attached to the gripper."""
        return [a.body for a in self._attached.values()]

    @property
    def attachments(self) -> list[Attachment]:
        """The objects attached to the gripper, each with where it sits relative to the TCP."""
        return list(self._attached.values())

    @property
    def finger_positions(self) -> np.ndarray:
        """The gripper joints' positions the scene's queries use."""
        return self.data.qpos[self._finger_qpos]

    def place(self, q: np.ndarray) -> None:
        """Puts the arm at ``q``, what it holds with it, without asking anything (:attr:`data` then shows it)."""
        self._place(np.asarray(q, dtype=float))

    # --- queries ---------------------------------------------------------------------------------------------

    def is_valid(self, q: np.ndarray) -> bool:
        """True if the arm at ``q`` is within its limits and nothing it holds or is made of collides."""
        return self.within_limits(q) and self.is_free(q)

    @timed("planning")
    def is_free(self, q: np.ndarray) -> bool:
        """True if nothing collides with the arm at ``q`` (joint limits not checked)."""
        self._place(q)
        if self._workspace is not None and self._links_outside():
            return False
        mujoco.mj_collision(self.model, self.data)
        ncon = self.data.ncon
        if ncon == 0:
            return True
        geoms = self.data.contact.geom[:ncon]
        bodies = self.model.geom_bodyid[geoms]
        refused = ~self._allowed[bodies[:, 0], bodies[:, 1]]
        if not refused.any():
            return True
        return self._only_leaving(bodies, refused)

    def _only_leaving(self, bodies: np.ndarray, refused: np.ndarray) -> bool:
        """Whether every refused contact is one being left: no deeper than where the motion started."""
        if not self._leaving:
            return False
        distances = self.data.contact.dist
        for k in np.flatnonzero(refused):
            floor = self._leaving.get((int(bodies[k, 0]), int(bodies[k, 1])))
            if floor is None or distances[k] < floor - LEAVING_TOLERANCE:
                return False
        return True

    @timed("planning")
    def collides_wherever_the_tcp_is(self, q: np.ndarray) -> bool:
        """Whether, with the arm at ``q``, something the TCP's pose alone places (the last link, the gripper, what
        it holds) collides with something the arm does not move: then every configuration that puts the TCP where
        ``q`` puts it collides too, and an IK search for that pose can stop."""
        self._place(q)
        mujoco.mj_collision(self.model, self.data)
        placed = self._placed_by_tcp.copy()
        placed[[attachment.body for attachment in self._attached.values()]] = True
        still = ~self._is_robot & ~placed
        distances = self.data.contact.dist
        for k, (a, b) in enumerate(self._contact_bodies()):
            if self._allowed[a, b]:
                continue
            floor = self._leaving.get((a, b))
            if floor is not None and distances[k] >= floor - LEAVING_TOLERANCE:
                continue
            if (placed[a] and still[b]) or (placed[b] and still[a]):
                return True
        return False

    @timed("planning")
    def collisions(self, q: np.ndarray) -> list[tuple[str, str]]:
        """The pairs of named things in collision (closer than the padding) with the arm at ``q``."""
        self._place(q)
        pairs = [(self.model.body(b).name, WORKSPACE) for b in self._links_outside()][:1]
        mujoco.mj_collision(self.model, self.data)
        moving = self._is_robot.copy()  # the robot and what it holds come first in each pair
        moving[[attachment.body for attachment in self._attached.values()]] = True
        distances = self.data.contact.dist
        for k, (a, b) in enumerate(self._contact_bodies()):
            floor = self._leaving.get((a, b))
            if floor is not None and distances[k] >= floor - LEAVING_TOLERANCE:
                continue
            if not self._allowed[a, b]:
                pair = (self.body_labels[a], self.body_labels[b])
                if moving[b] and not moving[a]:
                    pair = pair[::-1]
                if pair not in pairs:
                    pairs.append(pair)
        return pairs

    def touching(self, a: str, b: str, q: np.ndarray) -> bool:
        """Whether ``a`` and ``b`` (names, or "gripper") are within the padding of each other with the arm at
        ``q``, allowed or not."""
        first, second = set(self._bodies_named(a)), set(self._bodies_named(b))
        self._place(q)
        mujoco.mj_collision(self.model, self.data)
        return any((x in first and y in second) or (y in first and x in second) for x, y in self._contact_bodies())

    @functools.cached_property
    def lever_arms(self) -> np.ndarray:
        """An upper bound, per arm joint, of how far any point of the arm (and what it holds) is from that joint.

        The distance between consecutive joint anchors is fixed by the link between them, so the chain of those
        distances to the TCP, plus 0.15 m for fingers and a held object, bounds it in every configuration.
        Multiplying by a joint's motion bounds the displacement it causes.
        """
        self._kinematics(np.clip(np.zeros(self.dof), self.joint_lower, self.joint_upper))
        anchors = [self.data.xanchor[int(self.model.dof_jntid[dof])].copy() for dof in self.robot.dof]
        anchors.append(self.data.site_xpos[self.robot.tcp_site].copy())
        links = [float(np.linalg.norm(b - a)) for a, b in itertools.pairwise(anchors)]
        return np.array([sum(links[k:]) + 0.15 for k in range(self.dof)])

    def tcp_pose(self, q: np.ndarray) -> Transform:
        """Forward kinematics of the TCP."""
        self._kinematics(q)
        site = self.robot.tcp_site
        return Transform.from_rotation(self.data.site_xpos[site], self.data.site_xmat[site].reshape(3, 3))

    # --- attachments and allowed contacts --------------------------------------------------------------------

    def attach(self, name: str, q: np.ndarray | None = None) -> Attachment:
        """Makes object ``name`` move with the gripper, keeping its present pose relative to the TCP.

        Contacts between it and the gripper are always allowed; those it has now with anything else (the table
        it is lifted from) are allowed until it has left them.
        """
        if name not in self.object_bodies:
            raise KeyError(f"no object named {name!r} to attach; objects: {', '.join(sorted(self.object_bodies))}")
        if name in self._attached:
            return self._attached[name]
        body = self.object_bodies[name]
        q = self.arm_positions() if q is None else np.asarray(q, dtype=float)
        tcp = self.tcp_pose(q)
        obj = Transform.from_rotation(self.data.xpos[body], self.data.xmat[body].reshape(3, 3))
        address = int(self.model.jnt_qposadr[self.model.body_jntadr[body]])
        attachment = Attachment(name, body, tcp.inverse().compose(obj).matrix(), address)
        self._set_bits(self._body_mask(body), "held", self.padding)
        mujoco.mj_collision(self.model, self.data)
        touching = {b for pair in self._contact_bodies() if body in pair for b in pair} - {body}
        self._allow_bodies([body], list(touching))
        self._attached[name] = attachment
        self._attached_allowed[name] = touching
        return attachment

    def detach(self, name: str) -> None:
        """Returns a held object to the environment (where it now lies is taken from the next :meth:`update`)."""
        attachment = self._attached.pop(name, None)
        if attachment is None:
            raise KeyError(f"{name!r} is not attached; attached: {', '.join(self._attached) or 'nothing'}")
        self._attached_allowed.pop(name)
        body = attachment.body
        self._set_bits(self._body_mask(body), "env", 0.0)
        self._allowed[body, :] = self._allowed[:, body] = False
        self._leaving = {pair: floor for pair, floor in self._leaving.items() if body not in pair}

    @property
    def attached(self) -> list[str]:
        return list(self._attached)

    @contextlib.contextmanager
    def part_following(self, name: str, q: np.ndarray) -> Iterator[bool]:
        """Within the block, the drawer or door ``name`` (a body of its own in this scene, with its joint) moves
        as if held by the hand from the arm at ``q``: its hinge turns as the TCP goes round it, its slide as the TCP
        goes along it. A door swung open sweeps toward the arm that swings it. Yields whether the scene could
        (a scene of observed surfaces has no joints): where not, the part stays where it is."""
        bodies = [b for b in self._bodies_named(name) if self.model.body_jntnum[b] > 0]
        if not bodies or self._following is not None:
            yield False
            return
        joint = int(self.model.body_jntadr[bodies[0]])
        address = int(self.model.jnt_qposadr[joint])
        start = float(self.data.qpos[address])
        tcp = self.tcp_pose(np.asarray(q, dtype=float)).position.copy()
        revolute = int(self.model.jnt_type[joint]) == int(mujoco.mjtJoint.mjJNT_HINGE)
        anchor, axis = self.data.xanchor[joint].copy(), self.data.xaxis[joint].copy()
        self._following = _FollowedPart(address, start, revolute, anchor, axis, tcp)
        try:
            yield True
        finally:
            self._following = None
            self.data.qpos[address] = start
            mujoco.mj_kinematics(self.model, self.data)

    @contextlib.contextmanager
    def ignoring_held(self) -> Iterator[None]:
        """Within this block, what the gripper holds collides with nothing: for questions about the hand once it
        has let go (can it leave the place where it puts something down?)."""
        geoms = np.isin(self.model.geom_bodyid, self.held_bodies) & self._collides
        saved = self.model.geom_contype[geoms].copy(), self.model.geom_conaffinity[geoms].copy()
        self.model.geom_contype[geoms], self.model.geom_conaffinity[geoms] = 0, 0
        try:
            yield
        finally:
            self.model.geom_contype[geoms], self.model.geom_conaffinity[geoms] = saved

    @contextlib.contextmanager
    def fingers_open(self) -> Iterator[None]:
        """Within this block, the gripper is fully open (every joint of its linkage at the open position, the
        model's reference elsewhere): for questions about the hand once it lets go, when the fingers spread to
        their full width whatever stands beside them."""
        saved = self.data.qpos[self._finger_qpos].copy()
        self.data.qpos[self._finger_qpos] = self._finger_open
        try:
            yield
        finally:
            self.data.qpos[self._finger_qpos] = saved

    @contextlib.contextmanager
    def held_clearance(self, clearance: float) -> Iterator[None]:
        """Within this block, what the gripper holds counts as colliding closer than ``clearance`` to anything
        (rather than the padding): for transfers, where a held object swinging a little must not graze what it
        passes."""
        geoms = np.isin(self.model.geom_bodyid, self.held_bodies) & self._collides
        saved = self.model.geom_margin[geoms].copy()
        self.model.geom_margin[geoms] = np.maximum(saved, clearance)
        self._sync_body_margins()
        try:
            yield
        finally:
            self.model.geom_margin[geoms] = saved
            self._sync_body_margins()

    def allow(self, a: str, b: str, allowed: bool = True) -> None:
        """Allows (or forbids again) contact between two named things, e.g. the fingers and an object to grasp.
        Forbidding also ends an allowance to leave (:meth:`allow_leaving`)."""
        first, second = self._bodies_named(a), self._bodies_named(b)
        self._allow_bodies(first, second, allowed)
        if not allowed:
            for i in first:
                for j in second:
                    self._leaving.pop((i, j), None)
                    self._leaving.pop((j, i), None)

    def allow_leaving(self, a: str, b: str, q: np.ndarray) -> None:
        """Lets two named things come closer than the padding, even touch, but never go deeper into each other
        than they are with the arm at ``q``: a motion may start in a contact (fingers round what they just let
        go, a link that ended a motion inside the padding) and leave it, or brush past, but not sweep through the
        thing. :meth:`allow` with False ends it."""
        first, second = self._bodies_named(a), self._bodies_named(b)
        floors = {(i, j): 0.0 for i in first for j in second}
        for (x, y), floor in self._contact_floors(q).items():
            pair = (x, y) if (x, y) in floors else (y, x)
            if pair in floors:
                floors[pair] = min(floors[pair], floor)
        # Measured anew each time: a contact left shallower than it was may not be pushed back in.
        for (i, j), floor in floors.items():
            self._leaving[(i, j)] = self._leaving[(j, i)] = floor

    @contextlib.contextmanager
    def leaving_where(self, q: np.ndarray) -> Iterator[None]:
        """Within this block, every contact the arm at ``q`` is in may be left but not deepened (as
        :meth:`allow_leaving` allows): for screens of a motion from where the arm is, which will be allowed the
        same before it is made (a pear that slipped 3 mm in the hand, lifted beside a UR5e's base, came within the
        padding of its upper arm, and every place pose's path screen failed at its start)."""
        saved = dict(self._leaving)
        for (a, b), floor in self._contact_floors(q).items():
            if not self._allowed[a, b] and (a, b) not in saved:
                floor = min(self._leaving.get((a, b), 0.0), floor)  # the pair may come in both orders
                self._leaving[(a, b)] = self._leaving[(b, a)] = floor
        try:
            yield
        finally:
            self._leaving = saved

    def _contact_floors(self, q: np.ndarray) -> dict[tuple[int, int], float]:
        """Each pair of bodies in contact with the arm at ``q`` (as MuJoCo orders it), with the least distance
        between them and no more than 0: how deep a contact being left may stay (:meth:`allow_leaving`)."""
        self._place(np.asarray(q, dtype=float))
        mujoco.mj_collision(self.model, self.data)
        floors: dict[tuple[int, int], float] = {}
        for k, pair in enumerate(self._contact_bodies()):
            floors[pair] = min(floors.get(pair, 0.0), float(self.data.contact.dist[k]))
        return floors

    def leaving_names(self) -> set[tuple[str, str]]:
        """The pairs allowed to be left (:meth:`allow_leaving`) as names, to carry them into a rebuilt scene."""
        return {(self.body_labels[a], self.body_labels[b]) for a, b in self._leaving if a < b}

    def has(self, name: str) -> bool:
        """Whether ``name`` (or "gripper", or "arm") names something in the scene."""
        return name in ("gripper", "arm") or name in self.body_labels

    def allowed_names(self) -> set[tuple[str, str]]:
        """The allowed contacts as pairs of names (gripper parts by their body names), to carry them into a
        rebuilt scene."""
        pairs = set()
        for a, b in zip(*np.nonzero(np.triu(self._allowed)), strict=True):
            pairs.add((self.body_labels[a], self.body_labels[b]))
        return pairs

    def _bodies_named(self, name: str) -> list[int]:
        if name == "gripper":
            return self._gripper_bodies.tolist()
        if name == "arm":  # the links that move, but for the gripper
            moving = set(self._moving_bodies.tolist()) - set(self._gripper_bodies.tolist())
            return sorted(moving)
        bodies = [b for b, label in enumerate(self.body_labels) if label == name]
        if not bodies:
            known = sorted({label for label in self.body_labels if label})
            raise KeyError(f"nothing named {name!r} in the planning scene; names: {', '.join(known)}, gripper")
        return bodies

    # --- internals -------------------------------------------------------------------------------------------

    def _kinematics(self, q: np.ndarray) -> None:
        self.data.qpos[self._qpos] = q
        mujoco.mj_kinematics(self.model, self.data)
        if self._following is not None:
            self._follow_part(self._following)
            mujoco.mj_kinematics(self.model, self.data)

    def _follow_part(self, part: _FollowedPart) -> None:
        """Sets the followed part's joint to where the TCP has taken it: the turn of the TCP about a hinge since the
        start, or its travel along a slide."""
        tcp = self.data.site_xpos[self.robot.tcp_site]
        if part.revolute:
            moved = float(turns_about(part.axis, part.anchor, part.tcp_start, tcp))
        else:
            moved = float((tcp - part.tcp_start) @ part.axis)
        self.data.qpos[part.address] = part.start + moved

    def _place(self, q: np.ndarray) -> None:
        """Kinematics with the arm at ``q`` and every held object carried along."""
        self._kinematics(q)
        if not self._attached:
            return
        # Called by the ten thousand while something is held: plain arrays, no transform objects.
        data, site, tcp = self.data, self.robot.tcp_site, self._tcp
        tcp[:3, :3] = data.site_xmat[site].reshape(3, 3)
        tcp[:3, 3] = data.site_xpos[site]
        for attachment in self._attached.values():
            pose = tcp @ attachment.tcp_to_object
            adr = attachment.qpos_address
            data.qpos[adr : adr + 3] = pose[:3, 3]
            mujoco.mju_mat2Quat(data.qpos[adr + 3 : adr + 7], pose[:3, :3].ravel())
        mujoco.mj_kinematics(self.model, data)

    def _contact_bodies(self) -> list[tuple[int, int]]:
        ncon = self.data.ncon
        if ncon == 0:
            return []
        bodies = self.model.geom_bodyid[self.data.contact.geom[:ncon]]
        return [(int(a), int(b)) for a, b in bodies]

    def _body_mask(self, body: int) -> np.ndarray:
        mask = np.zeros(self.model.nbody, dtype=bool)
        mask[body] = True
        return mask

    def _allow_bodies(self, first: Iterable[int], second: Iterable[int], allowed: bool = True) -> None:
        second = list(second)
        for i in first:
            for j in second:
                self._allowed[i, j] = self._allowed[j, i] = allowed

    def _set_bits(self, bodies: np.ndarray, role: str, margin: float) -> None:
        """Collision bits of a role, and margin (MuJoCo reports pairs closer than the larger margin), of geoms."""
        geoms = bodies[self.model.geom_bodyid] & self._collides
        self.model.geom_contype[geoms], self.model.geom_conaffinity[geoms] = _BITS[role]
        self.model.geom_margin[geoms] = margin
        self._sync_body_margins()

    def _sync_body_margins(self) -> None:
        """Each body's margin, the largest of its colliding geoms'. MuJoCo's midphase prunes pairs of bodies of
        several geoms each by the body margins compiled into the model (zero here), not by the geoms': without
        this a gripper link 2.7 mm above the table (the padding is 5 mm) passed as free."""
        if not self._pad_bodies:
            return
        margins = np.zeros(self.model.nbody)
        geoms = np.flatnonzero(self._collides)
        np.maximum.at(margins, self.model.geom_bodyid[geoms], self.model.geom_margin[geoms])
        self.model.body_margin[:] = margins


def _moved_by_arm(model: mujoco.MjModel, body: int, robot: RobotBinding) -> bool:
    arm_dofs = set(robot.dof.tolist())
    while body > 0:
        if model.body_dofnum[body] > 0 and model.body_dofadr[body] in arm_dofs:
            return True
        body = model.body_parentid[body]
    return False


def _open_finger_positions(
    model: mujoco.MjModel, robot: RobotBinding, gripper_bodies: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The qpos addresses of the gripper's joints and their values when it is fully open: the description's open
    positions for its driven joints, the model's reference for the rest of a linkage (open at zero, as the 2F-85's
    followers are)."""
    open_by_name = dict(
        zip(
            (RobotDescription.qualified(j) for j in robot.description.gripper.joints),
            robot.description.gripper.open_qpos,
            strict=True,
        )
    )
    joints = [j for j in range(model.njnt) if model.jnt_bodyid[j] in set(gripper_bodies.tolist())]
    addresses = np.array([model.jnt_qposadr[j] for j in joints], dtype=int)
    values = np.array([open_by_name.get(model.joint(j).name, model.qpos0[model.jnt_qposadr[j]]) for j in joints])
    return addresses, values
