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
from collections.abc import Iterator
from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.geometry import Transform
from roboscript.phases import timed
from roboscript.planning.allowed_pairs import AllowedPairs
from roboscript.planning.collision_roles import assign_roles, open_finger_positions, set_role, sync_body_margins
from roboscript.planning.followed_part import FollowedPart
from roboscript.robots.mujoco_model import RobotBinding

REGRASP_LIMIT = 0.05  # metres a held object may have shifted in the hand and still be where the scene holds it
WORKSPACE_MARGIN = 0.02  # metres the arm's links keep inside a workspace box: a timed trajectory between two
# checked configurations, and the backend's own check, must not find a link just outside it
WORKSPACE = "workspace box"  # what a link leaving the box is reported in collision with

@dataclass(frozen=True)
class Attachment:
    """An object held by the gripper: its pose relative to the TCP, and contacts allowed until it leaves them."""

    name: str
    body: int
    tcp_to_object: np.ndarray  # 4x4
    qpos_address: int  # where the object's free joint keeps its pose in qpos


class PlanningScene:
    """Collision queries for arm configurations against the world, with attached objects and allowed pairs."""

    def __init__(
        self,
        model: mujoco.MjModel,
        robot: RobotBinding,
        body_labels: list[str],
        object_bodies: dict[str, int],
        padding: float = 0.005,
    ):
        if padding < 0:
            raise ValueError(f"padding must be >= 0 metres, got {padding}")
        self.model = model
        self.data = mujoco.MjData(model)
        self.robot = robot
        self.padding = padding
        self.body_labels = body_labels
        self.object_bodies = object_bodies
        self._qpos = robot.qpos
        # Queries call mj_kinematics and mj_collision directly; sleeping would make them skip bodies.
        model.opt.enableflags &= ~int(mujoco.mjtEnableBit.mjENBL_SLEEP)

        self.colliding_geoms = (model.geom_contype | model.geom_conaffinity) > 0
        bodies = assign_roles(model, robot, padding, self.colliding_geoms)
        self.sync_body_margins()
        self._is_robot, self._gripper_bodies = bodies.is_robot, bodies.gripper
        self._placed_by_tcp, self._moving_bodies = bodies.placed_by_tcp, bodies.moving

        self._pairs = AllowedPairs(model.nbody)
        self._attached: dict[str, Attachment] = {}
        self._following: FollowedPart | None = None
        self._attached_allowed: dict[str, set[int]] = {}
        self._lower, self._upper = robot.joint_lower - 1e-9, robot.joint_upper + 1e-9
        self.finger_qpos, self.finger_open = open_finger_positions(model, robot, self._gripper_bodies)
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
                        self._pairs.allowed[body, other] = self._pairs.allowed[other, body] = False

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
        return self.data.qpos[self.finger_qpos]

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
        refused = ~self._pairs.allowed[bodies[:, 0], bodies[:, 1]]
        if not refused.any():
            return True
        # Free still if every refused contact is one being left: no deeper than where the motion started.
        distances = self.data.contact.dist[:ncon]
        return bool(self._pairs.leaving) and self._pairs.leaving_only(bodies[refused], distances[refused])

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
            if self._pairs.permits(a, b, distances[k]):
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
            if self._pairs.permits(a, b, distances[k]):
                continue
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
        self._pairs.allow([body], list(touching))
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
        self._pairs.release(body)

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
        tcp = self.tcp_pose(np.asarray(q, dtype=float)).position
        part = self._following = FollowedPart.of(self.model, self.data, bodies[0], tcp)
        try:
            yield True
        finally:
            self._following = None
            self.data.qpos[part.address] = part.start
            mujoco.mj_kinematics(self.model, self.data)

    def allow(self, a: str, b: str, allowed: bool = True) -> None:
        """Allows (or forbids again) contact between two named things, e.g. the fingers and an object to grasp.
        Forbidding also ends an allowance to leave (:meth:`allow_leaving`)."""
        self._pairs.allow(self._bodies_named(a), self._bodies_named(b), allowed)

    def allow_leaving(self, a: str, b: str, q: np.ndarray) -> None:
        """Lets two named things come closer than the padding, even touch, but never go deeper into each other
        than they are with the arm at ``q``: a motion may start in a contact (fingers round what they just let
        go, a link that ended a motion inside the padding) and leave it, or brush past, but not sweep through the
        thing. :meth:`allow` with False ends it."""
        self._pairs.leave(self._bodies_named(a), self._bodies_named(b), self._contact_floors(q))

    @contextlib.contextmanager
    def leaving_where(self, q: np.ndarray) -> Iterator[None]:
        """Within this block, every contact the arm at ``q`` is in may be left but not deepened (as
        :meth:`allow_leaving` allows): for screens of a motion from where the arm is, which will be allowed the
        same before it is made (a pear that slipped 3 mm in the hand, lifted beside a UR5e's base, came within the
        padding of its upper arm, and every place pose's path screen failed at its start)."""
        saved = dict(self._pairs.leaving)
        self._pairs.leave_all(self._contact_floors(q))
        try:
            yield
        finally:
            self._pairs.leaving = saved

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
        return self._pairs.leaving_names(self.body_labels)

    def has(self, name: str) -> bool:
        """Whether ``name`` (or "gripper", or "arm") names something in the scene."""
        return name in ("gripper", "arm") or name in self.body_labels

    def allowed_names(self) -> set[tuple[str, str]]:
        """The allowed contacts as pairs of names (gripper parts by their body names), to carry them into a
        rebuilt scene."""
        return self._pairs.allowed_names(self.body_labels)

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
            part = self._following
            self.data.qpos[part.address] = part.value(self.data.site_xpos[self.robot.tcp_site])
            mujoco.mj_kinematics(self.model, self.data)

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

    def _set_bits(self, bodies: np.ndarray, role: str, margin: float) -> None:
        """Collision bits of a role, and margin (MuJoCo reports pairs closer than the larger margin), of geoms."""
        set_role(self.model, bodies[self.model.geom_bodyid] & self.colliding_geoms, role, margin)
        self.sync_body_margins()

    def sync_body_margins(self) -> None:
        """Each body's margin from its geoms' (see :func:`~roboscript.planning.collision_roles.sync_body_margins`)."""
        sync_body_margins(self.model, self.colliding_geoms)

