"""The compartment behind a cabinet door, from what the cameras saw: how far the door stands open, and the free
inside behind it where things put in through it go.

A door turns about its hinge, and seen from above its front is a line through the hinge: the door stands open by the
angle that line has turned since the door was first seen (taken as shut). The inside is the cabinet's, behind the front
the door closed: across and back as far as the cabinet's top reaches (less its panels), and up and down as far as the
door's own front reaches (a door fills its opening).
"""

from __future__ import annotations

import numpy as np

from roboscript.errors import FailureError
from roboscript.geometry import Transform, turns_about
from roboscript.perception.base import ArticulationJoint, Receptacle
from roboscript.perception.detection.furniture_parts import LEVEL, TOP_BAND

PANEL = 0.015  # metres: a cabinet's side, back and top panels
DOOR_BEHIND = 0.02  # metres behind the front's plane the inside starts: the door's thickness, and a margin
FLOOR_SEARCH = 0.03  # metres about the door's lowest points within which the compartment's floor is looked for
FACING_UP = 0.9  # least vertical component of the normal of a point on the floor
MIN_FLOOR_POINTS = 20  # fewer points seen on the floor: it is taken at the door's bottom edge
MIN_TOP_POINTS = 20  # fewer points on the cabinet's top: its extent is not known
BEHIND_FRONT = 0.015  # metres behind the shut front's plane a door's point may still lie (noise, its thickness)
NEAR_HINGE = 0.05  # metres: a door's points this near its hinge turn too little to tell its angle
EDGE_RANK = 5  # the top's edges: their points' 5th outermost (a camera sees a top thinly near its edges)


class CompartmentUnseenError(FailureError, ValueError):
    """Too little of the cabinet or its door was seen to tell where the compartment is."""


def door_angle(joint: ArticulationJoint, shut_front: np.ndarray, front_now: np.ndarray) -> float:
    """How far (radians, positive: open) the door has turned about its hinge ``joint`` since a point of its front
    stood at ``shut_front`` (shut), from its front's points now, ``front_now`` (n, 3): the median of their turns
    about the hinge (those within :data:`NEAR_HINGE` of it say little)."""
    axis = np.asarray(joint.axis, dtype=float)
    then = _about(np.asarray(shut_front, dtype=float) - joint.position, axis)
    points = np.atleast_2d(np.asarray(front_now, dtype=float))
    now = _about(points - joint.position, axis)
    # What stands behind the front's plane is not the door: its boxes in the images take in the inside it opens on.
    not_behind = now @ closed_facing(joint, shut_front) > -BEHIND_FRONT
    kept = (np.linalg.norm(now, axis=1) > NEAR_HINGE) & not_behind
    if np.linalg.norm(then) < 1e-6 or not kept.any():
        return 0.0
    return float(np.median(turns_about(axis, joint.position, shut_front, points[kept])))


def closed_facing(joint: ArticulationJoint, shut_front: np.ndarray) -> np.ndarray:
    """The horizontal direction out of the cabinet's front, from the hinge and a point of the door's front shut:
    a positive turn about the axis swings the front out, so out is the axis crossed with the way from the hinge
    along the front."""
    axis = np.asarray(joint.axis, dtype=float)
    out = np.cross(axis, _about(np.asarray(shut_front, dtype=float) - joint.position, axis))
    out[2] = 0.0
    length = float(np.linalg.norm(out))
    if length < 1e-6:
        raise CompartmentUnseenError(f"{joint.part!r}: its front was seen on its hinge only; no front to tell")
    return out / length


def compartment_inside(
    name: str,
    joint: ArticulationJoint,
    shut_front: np.ndarray,
    carcass_points: np.ndarray,
    carcass_normals: np.ndarray,
    door_points: np.ndarray,
) -> Receptacle:
    """The free inside behind the door ``name``: in a frame on its hinge's foot with x out of the front and z up."""
    facing = closed_facing(joint, shut_front)
    up = np.array([0.0, 0.0, 1.0])
    frame = Transform.from_rotation(
        np.array([joint.position[0], joint.position[1], 0.0]), np.column_stack([facing, np.cross(up, facing), up])
    )
    local = frame.inverse().apply(carcass_points)
    normals = np.asarray(carcass_normals, dtype=float)
    top = float(np.nanpercentile(carcass_points[:, 2], 99))
    on_top = (np.nan_to_num(normals[:, 2]) > LEVEL) & (carcass_points[:, 2] > top - TOP_BAND)
    if on_top.sum() < MIN_TOP_POINTS or len(door_points) < 10:
        raise CompartmentUnseenError(
            f"{name!r}: the cabinet's top ({int(on_top.sum())} points) or the door ({len(door_points)} points) was "
            "seen too little to tell where the compartment behind it is"
        )
    x, y = np.sort(local[on_top, 0]), np.sort(local[on_top, 1])
    rank = min(EDGE_RANK, len(x) - 1)
    front, back = x[-1 - rank], x[rank]
    left, right = y[rank], y[-1 - rank]
    low, high = np.percentile(door_points[:, 2], [1, 99])
    inside = (local[:, 0] < front - DOOR_BEHIND) & (local[:, 0] > back + PANEL)
    floor_seen = inside & (np.abs(local[:, 2] - low) < FLOOR_SEARCH) & (np.nan_to_num(normals[:, 2]) > FACING_UP)
    floor = float(np.median(local[floor_seen, 2])) if floor_seen.sum() >= MIN_FLOOR_POINTS else float(low)
    lower = np.array([back + PANEL, left + PANEL, floor])
    upper = np.array([front - DOOR_BEHIND, right - PANEL, float(high)])
    return Receptacle(name, frame, lower, upper)


def _about(offset: np.ndarray, axis: np.ndarray) -> np.ndarray:
    """``offset`` (3,) or (n, 3) with its part along ``axis`` taken out: as seen looking down the axis."""
    return offset - np.asarray(offset @ axis)[..., None] * axis
