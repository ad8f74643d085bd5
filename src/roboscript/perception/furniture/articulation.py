"""Articulation from points: a drawer's sliding axis and a door's hinge line, from the points of its front panel
and the centre of its handle (the geometric estimator of the full-perception mode).

A drawer slides along the normal of its front. A door turns about the vertical edge of its front farthest from
its handle. Both are given in the form ground truth uses (:class:`ArticulationJoint`): the axis point on the
front's plane, the axis signed so that positive values open. How far a part is open cannot be told from one look
at its front, so ``value`` is 0 and the limits are the usual travel of such parts.
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.geometry import Transform, quat_from_axis_angle, turns_about
from roboscript.perception.base import ArticulationJoint

DRAWER_TRAVEL = 0.3  # metres a drawer is assumed to slide out at most
DOOR_TRAVEL = math.pi / 2  # radians a door is assumed to open at most
PLANE_TOLERANCE = 0.004  # metres from the plane within which a point is on the front
MAX_TILT = 0.3  # largest vertical component of a front's normal (fronts of drawers and doors stand upright)
HANDLE_REACH = 0.1  # metres a handle stands out of its front at most
FACING = 0.8  # least |cos| between a point's normal and a plane's for the point to lie on that face


def front_plane(
    points: np.ndarray,
    toward: np.ndarray,
    iterations: int = 200,
    seed: int = 0,
    normals: np.ndarray | None = None,
):
    """``(point, normal)`` of the dominant upright plane of ``points`` (RANSAC, then a least-squares refit on its
    inliers), the normal turned towards ``toward`` (the handle, which stands out of the front). Only upright
    planes count, and only those ``toward`` stands at most :data:`HANDLE_REACH` out of: an open drawer shows the
    cameras above it more of its bottom, and of its back wall, than of its front. Given the points' ``normals``,
    a point counts for a plane only where it faces the plane's way: the strip of a pulled drawer's bottom that a
    vertical plane cuts through is no face (with the arm at the handle, such strips outnumbered the front's points
    seen)."""
    if len(points) < 10:
        raise ValueError(f"a front needs at least 10 points, got {len(points)}")
    rng = np.random.default_rng(seed)
    toward = np.asarray(toward, dtype=float)
    pool = np.arange(len(points))
    facing = None
    if normals is not None:  # planes are drawn through points on upright faces: a front, not the bottom before it
        upright = np.flatnonzero(np.abs(np.nan_to_num(normals[:, 2], nan=1.0)) < MAX_TILT)
        pool = upright if len(upright) >= 10 else pool
        facing = np.nan_to_num(normals)
    # Every hypothesis at once: the same draws, and the same winner (the first with most inliers), as one at a time.
    draws = np.array([rng.choice(pool, 3, replace=False) for _ in range(iterations)]).reshape(-1, 3)
    anchors = points[draws[:, 0]]
    planes = np.cross(points[draws[:, 1]] - anchors, points[draws[:, 2]] - anchors)
    lengths = np.linalg.norm(planes, axis=1)
    usable = lengths >= 1e-9
    planes[usable] /= lengths[usable, None]
    usable &= np.abs(planes[:, 2]) <= MAX_TILT
    usable &= np.abs(np.einsum("ij,ij->i", toward - anchors, planes)) <= HANDLE_REACH
    best, most = np.zeros(len(points), dtype=bool), 0
    for chunk in np.array_split(np.flatnonzero(usable), max(1, int(usable.sum()) * len(points) // 1_000_000)):
        if len(chunk) == 0:
            continue
        offsets = np.einsum("ij,ij->i", anchors[chunk], planes[chunk])
        inliers = np.abs(planes[chunk] @ points.T - offsets[:, None]) < PLANE_TOLERANCE
        if facing is not None:
            inliers &= np.abs(planes[chunk] @ facing.T) > FACING
        counts = inliers.sum(axis=1)
        k = int(np.argmax(counts))
        if counts[k] > most:
            best, most = inliers[k], int(counts[k])
    if best.sum() < 10:
        raise ValueError(
            f"no upright plane of at least 10 points within {HANDLE_REACH} m of the handle among the {len(points)} "
            "points of a front"
        )
    on_plane = points[best]
    center = on_plane.mean(axis=0)
    normal = np.linalg.svd(on_plane - center, full_matrices=False)[2][-1]
    if np.dot(normal, toward - center) < 0:
        normal = -normal
    return center, normal / np.linalg.norm(normal), on_plane


def drawer_joint(
    part: str, front_points: np.ndarray, handle_center: np.ndarray, normals: np.ndarray | None = None
) -> ArticulationJoint:
    """The prismatic joint of a drawer: along its front's outward normal, through the handle's foot on the
    front (``normals``: the front points', where known)."""
    return estimate_joint("prismatic", part, front_points, handle_center, normals)[0]


def door_joint(
    part: str, front_points: np.ndarray, handle_center: np.ndarray, normals: np.ndarray | None = None
) -> ArticulationJoint:
    """The revolute joint of a door: the vertical line through the edge of its front farthest from the handle,
    signed so that turning by a positive angle swings the handle out of the front."""
    return estimate_joint("revolute", part, front_points, handle_center, normals)[0]


def estimate_joint(
    kind: str, part: str, front_points: np.ndarray, handle_center: np.ndarray, normals: np.ndarray | None = None
) -> tuple[ArticulationJoint, int]:
    """:func:`drawer_joint` (``kind`` prismatic) or :func:`door_joint` (revolute), with how many points of the
    front bore the plane it was estimated from."""
    center, normal, on_plane = front_plane(front_points, handle_center, normals=normals)
    if kind == "prismatic":
        foot = handle_center - np.dot(handle_center - center, normal) * normal
        return ArticulationJoint(part, "prismatic", foot, normal, 0.0, 0.0, DRAWER_TRAVEL), len(on_plane)
    return _door(part, center, normal, on_plane, handle_center), len(on_plane)


def moved_with_handle(joint: ArticulationJoint, old_handle: np.ndarray, handle_center: np.ndarray):
    """A joint estimated when the handle stood at ``old_handle``, now that it stands at ``handle_center``: a
    drawer's line slides with it; a door's hinge stays where it is."""
    if joint.type != "prismatic":
        return joint
    axis = np.asarray(joint.axis, dtype=float)
    shift = float(np.dot(np.asarray(handle_center) - np.asarray(old_handle), axis)) * axis
    return ArticulationJoint(joint.part, joint.type, joint.position + shift, axis, 0.0, joint.lower, joint.upper)


def part_motion(joint: ArticulationJoint, hand_from: np.ndarray, hand_to: np.ndarray) -> Transform:
    """How a part moved on ``joint`` while the hand that held it went from ``hand_from`` to ``hand_to`` (TCP
    positions): a door turned about its hinge by the angle the hand went round it, a drawer slid along its line by
    the hand's way along it. Not the hand's own motion: the fingers turn about a handle's bar as a door swings, and
    the door's far edge, moved with the hand, stood centimetres off."""
    axis = np.asarray(joint.axis, dtype=float) / np.linalg.norm(joint.axis)
    hand_from, hand_to = np.asarray(hand_from, dtype=float), np.asarray(hand_to, dtype=float)
    if joint.type == "revolute":
        pivot = np.asarray(joint.position, dtype=float)
        turn = Transform(np.zeros(3), quat_from_axis_angle(axis, float(turns_about(axis, pivot, hand_from, hand_to))))
        return Transform(pivot - turn.rotation @ pivot, turn.quaternion)
    return Transform(float(np.dot(hand_to - hand_from, axis)) * axis, np.array([0.0, 0.0, 0.0, 1.0]))


def _door(
    part: str, center: np.ndarray, normal: np.ndarray, on_plane: np.ndarray, handle_center: np.ndarray
) -> ArticulationJoint:
    up = np.array([0.0, 0.0, 1.0])
    across = np.cross(up, normal)
    across /= np.linalg.norm(across)
    extent = (on_plane - center) @ across
    handle = float(np.dot(handle_center - center, across))
    lo, hi = np.percentile(extent, 1), np.percentile(extent, 99)
    edge = lo if abs(handle - lo) > abs(handle - hi) else hi
    height = float(np.dot(handle_center - center, up))
    hinge = center + edge * across + height * up
    axis = up if np.dot(np.cross(up, handle_center - hinge), normal) > 0 else -up
    return ArticulationJoint(part, "revolute", hinge, axis, 0.0, 0.0, DOOR_TRAVEL)
