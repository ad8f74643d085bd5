"""Exhaustive collision checks along straight joint-space segments, placed by how far the arm really moves.

A segment is safe when its checked configurations are free (nothing within the scene's padding) and no point of
the arm, or of what it holds, travels more than ``step`` metres between two consecutive checks. The classic bound
on that travel, the sum over joints of each joint's turn times a lever arm good for every configuration
(:func:`roboscript.planning.planner.densify`), is loose: along a Cartesian step of 5 mm at the hand it asks for a
dozen checks, because joints that turn against each other (shoulder and elbow keeping the hand level) are counted
as if their motions added up.

:class:`ArmTravel` bounds the travel from the two ends of the segment instead. For any point ``p`` of a body
``b``, moved by revolute joints along ``q(s) = q0 + s dq``:

- from ``s = 0`` to ``1`` it moves by at most ``|x_b(1) - x_b(0)| + 2 sin(theta_b / 2) R_b`` (the body's origin
  moves by the first term, its rotation by ``theta_b`` moves a point within ``R_b`` of the origin by the second);
- the speed ``|p'(s)|`` differs from that mean by at most ``K / 2``, where ``K`` bounds ``|p''|``:
  ``d2p / dq_j dq_k = w_j x (w_k x (p - a_k))`` for ``j <= k`` has a length of at most ``|p - a_k| <= L_k``, so
  ``|p''| <= sum_jk |dq_j| |dq_k| L_max(j,k) <= (sum_j |dq_j|) (sum_k |dq_k| L_k)``, with ``L_k`` decreasing
  along the chain.

So the travel over a fraction ``h`` of the segment is at most ``h (D + K / 2)``, ``D`` being the largest of the
first bounds. ``K`` grows with the square of the segment, so a long segment is first cut into pieces short enough
that ``K`` stays below the step.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.planning.scene import PlanningScene
from roboscript.robots.mujoco_model import is_descendant


@dataclass(frozen=True)
class Blocked:
    """Where a path was found blocked: in segment ``segment`` (from waypoint ``segment`` to the next, or the
    waypoint itself for a path of one), at fraction ``fraction`` of it, in configuration ``q``."""

    segment: int
    fraction: float
    q: np.ndarray


class ArmTravel:
    """Bounds on how far any point of the arm, and of what it holds, travels along a joint-space segment.

    Made for the scene as it is (what it holds, the fingers' opening), placed in any configuration: make a new one
    when that changes.
    """

    def __init__(self, scene: PlanningScene):
        model, robot = scene.model, scene.robot
        jnt = model.dof_jntid[robot.dof]
        if np.any(model.jnt_type[jnt] != mujoco.mjtJoint.mjJNT_HINGE):
            raise ValueError("ArmTravel bounds revolute arms only; this arm has a joint that is not a hinge")
        self.scene = scene
        joint_bodies = model.dof_bodyid[robot.dof]
        bodies, last_joint = [], []
        for b in scene.moving_bodies:
            moved_by = [k for k, jb in enumerate(joint_bodies) if is_descendant(model, b, jb)]
            bodies.append(int(b))
            last_joint.append(max(moved_by))
        for b in scene.held_bodies:
            bodies.append(int(b))
            last_joint.append(len(joint_bodies) - 1)
        radius = np.array([_collision_radius(model, b) for b in bodies])
        keep = radius > 0  # a body with nothing that collides cannot be in the way
        self.bodies = np.array(bodies, dtype=int)[keep]
        self.radius = radius[keep]
        self._last_joint = np.array(last_joint, dtype=int)[keep]
        self._joints = jnt
        self.levers = self._measure_levers()

    def positions(self) -> tuple[np.ndarray, np.ndarray]:
        """The bodies' origins and orientations (quaternions) in the scene's present configuration."""
        data = self.scene.data
        return data.xpos[self.bodies], data.xquat[self.bodies]

    def _measure_levers(self) -> np.ndarray:
        """Per arm joint ``k``, a bound ``L_k`` on the distance from its anchor to any point it moves, in every
        configuration: the chain of anchor-to-anchor distances (fixed by the links) to the joint that moves a body
        last, that joint's (fixed) distance to the body's origin, and the body's radius. Reads the scene's present
        configuration, in which only these fixed distances are taken."""
        data = self.scene.data
        anchors = data.xanchor[self._joints]
        links = np.linalg.norm(np.diff(anchors, axis=0), axis=1)
        from_anchor = np.linalg.norm(data.xpos[self.bodies] - anchors[self._last_joint], axis=1) + self.radius
        chain = np.concatenate([[0.0], np.cumsum(links)])  # chain[k]: from joint 0's anchor to joint k's
        levers = np.zeros(len(self._joints))
        for k in range(len(self._joints)):
            beyond = self._last_joint >= k
            reach = chain[self._last_joint[beyond]] - chain[k] + from_anchor[beyond]
            levers[k] = float(reach.max()) if reach.size else 0.0
        return levers

    def curvature(self, dq: np.ndarray) -> float:
        """``K``: a bound on ``|p''|`` of any point along the segment ``dq`` (metres)."""
        turns = np.abs(dq)
        return float(turns.sum() * (turns @ self.levers))

    def travel(
        self, before: tuple[np.ndarray, np.ndarray], after: tuple[np.ndarray, np.ndarray], dq: np.ndarray
    ) -> float:
        """A bound on the path length of any point along the segment ``dq`` whose ends put the bodies at
        ``before`` and ``after`` (see the module's text)."""
        shift = np.linalg.norm(after[0] - before[0], axis=1)
        cos_half = np.minimum(np.abs(np.einsum("ij,ij->i", after[1], before[1])), 1.0)
        turn = 2.0 * np.sqrt(1.0 - cos_half * cos_half) * self.radius  # 2 sin(theta / 2) R
        return float((shift + turn).max()) + self.curvature(dq) / 2


_travels: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()  # scene -> (what it was made for, ArmTravel)


def arm_travel(scene: PlanningScene) -> ArmTravel:
    """The scene's :class:`ArmTravel` for what it holds (and where in the hand) and its fingers' opening now, its
    levers measured; made again only when those change. Call with the scene placed (:meth:`PlanningScene.place`
    or a query)."""
    held = tuple((a.body, a.tcp_to_object.tobytes()) for a in scene.attachments)
    key = (held, scene.finger_positions.tobytes())
    kept = _travels.get(scene)
    if kept is not None and kept[0] == key:
        return kept[1]
    travel = ArmTravel(scene)
    _travels[scene] = (key, travel)
    return travel


def first_blocked(scene: PlanningScene, waypoints: np.ndarray, step: float, check_start: bool = True) -> Blocked | None:
    """The first place along the polyline ``waypoints`` found in collision or outside the joint limits, or None
    if none is: configurations are checked close enough that no point of the arm travels more than ``step``
    metres between two. With ``check_start`` False the first waypoint is taken as checked already."""
    waypoints = np.asarray(waypoints, dtype=float)
    # Points between in-limit points are within the limits too (the limits are a box); test only the ends.
    for index in (0, len(waypoints) - 1):
        if (index > 0 or check_start) and not scene.within_limits(waypoints[index]):
            return Blocked(max(index - 1, 0), 1.0 if index else 0.0, waypoints[index])
    if check_start:
        if not scene.is_free(waypoints[0]):
            return Blocked(0, 0.0, waypoints[0])
    else:
        scene.place(waypoints[0])
    travel = arm_travel(scene)
    here = travel.positions()
    for segment in range(len(waypoints) - 1):
        blocked, here = _along_segment(scene, travel, waypoints[segment], waypoints[segment + 1], here, step)
        if blocked is not None:
            return Blocked(segment, *blocked)
    return None


def _along_segment(
    scene: PlanningScene,
    travel: ArmTravel,
    a: np.ndarray,
    b: np.ndarray,
    at_a: tuple[np.ndarray, np.ndarray],
    step: float,
) -> tuple[tuple[float, np.ndarray] | None, tuple[np.ndarray, np.ndarray]]:
    """Checks the segment from ``a`` (checked, its bodies at ``at_a``) to ``b``, the end included. Returns the
    fraction and configuration of the first collision found (or None), and the bodies' positions at ``b``."""
    dq = b - a
    # Pieces short enough that the curvature term stays under half a step in each.
    pieces = max(1, math.ceil(math.sqrt(travel.curvature(dq) / step)))
    start, before = 0.0, at_a
    for piece in range(1, pieces + 1):
        end = piece / pieces
        q_end = a + dq * end
        end_free = scene.is_free(q_end)
        after = travel.positions()
        checks = max(1, math.ceil(travel.travel(before, after, dq * (end - start)) / step))
        for k in range(1, checks):
            s = start + (end - start) * k / checks
            q = a + dq * s
            if not scene.is_free(q):
                return (s, q), after
        if not end_free:
            return (end, q_end), after
        start, before = end, after
    return None, before


def _collision_radius(model: mujoco.MjModel, body: int) -> float:
    """The radius about ``body``'s origin of a sphere holding every geom of it that collides (0 if none does)."""
    geoms = np.flatnonzero(model.geom_bodyid == body)
    geoms = geoms[(model.geom_contype[geoms] | model.geom_conaffinity[geoms]) > 0]
    if geoms.size == 0:
        return 0.0
    return float(np.max(np.linalg.norm(model.geom_pos[geoms], axis=1) + model.geom_rbound[geoms]))
