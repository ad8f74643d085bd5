"""Where a held object can go: free spots inside a receptacle, on the table, or at a given position.

Candidates are object positions (the centre of the object's box) with a yaw turn; the tool layer turns them into
gripper poses and keeps the first one the arm can reach. A spot is free when the object's footprint, with a margin,
stays inside the receptacle's interior and clear of every other object's box.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.base import Receptacle

MARGIN = 0.007  # clearance kept from walls and from other objects
DROP = 0.012  # the object is released this far above its support


class PlacementError(RuntimeError):
    """No free, reachable spot was found; the message says what was in the way."""


class ReceptacleFullError(PlacementError):
    """The receptacle has no free spot large enough for the object."""


@dataclass(frozen=True)
class PlacementSpot:
    """The object's box centre after placement, and the yaw turn (radians) about world z from its present pose;
    ``score`` orders spots (higher first)."""

    center: np.ndarray
    yaw: float
    score: float


def _rotated_half(half_xy: np.ndarray, yaw: float) -> np.ndarray:
    c, s = abs(math.cos(yaw)), abs(math.sin(yaw))
    return np.array([c * half_xy[0] + s * half_xy[1], s * half_xy[0] + c * half_xy[1]])


def _clearance(center_xy: np.ndarray, half_xy: np.ndarray, obstacles: list[Box3D]) -> float:
    """Smallest gap between the footprint and any obstacle box (negative: overlap)."""
    best = 1.0
    for box in obstacles:
        gap = np.maximum(np.abs(center_xy - box.center[:2]) - half_xy - box.size[:2] / 2, 0.0)
        overlap = np.all(np.abs(center_xy - box.center[:2]) < half_xy + box.size[:2] / 2)
        distance = -0.001 if overlap else float(np.linalg.norm(gap))
        best = min(best, distance)
    return best


def spots_in_receptacle(
    receptacle: Receptacle,
    half_xy: np.ndarray,
    object_yaw: float,
    height: float,
    obstacles: list[Box3D],
    corner_xy: np.ndarray,
    step: float = 0.015,
    near_xy: np.ndarray | None = None,
    wall_margin: float = MARGIN,
) -> list[PlacementSpot]:
    """Free spots inside the receptacle's interior, filled from the corner nearest ``corner_xy`` outwards.

    The object (footprint half-extents ``half_xy`` in its own frame, turned by ``object_yaw``) is turned square to
    the receptacle in each of four ways. Filling from one corner, like packing a box, leaves the most room for
    what comes next; the corner nearest the robot keeps the arm's reach short. With ``near_xy`` (putting
    something aside on the table) the spots nearest that point come first instead.
    """
    lower, upper = receptacle.lower, receptacle.upper
    rotation = receptacle.frame.rotation
    frame_yaw = math.atan2(rotation[1, 0], rotation[0, 0])
    bottom = receptacle.frame.apply(np.array([[0.0, 0.0, lower[2]]]))[0, 2]
    local_corner = receptacle.frame.inverse().apply(np.array([[*corner_xy, bottom]]))[0, :2]
    corner = np.clip(local_corner, lower[:2], upper[:2])
    corner = np.where(np.abs(corner - lower[:2]) < np.abs(corner - upper[:2]), lower[:2], upper[:2])
    out: list[PlacementSpot] = []
    for quarter in range(4):
        aligned = frame_yaw + quarter * math.pi / 2
        turn = math.remainder(aligned - object_yaw, 2 * math.pi)
        half = (half_xy if quarter % 2 == 0 else half_xy[::-1]) + wall_margin
        lo, hi = lower[:2] + half, upper[:2] - half
        if np.any(hi < lo - 1e-9):
            continue
        xs = np.arange(lo[0], hi[0] + 1e-9, step) if hi[0] - lo[0] > step else np.array([(lo[0] + hi[0]) / 2])
        ys = np.arange(lo[1], hi[1] + 1e-9, step) if hi[1] - lo[1] > step else np.array([(lo[1] + hi[1]) / 2])
        world_half = _rotated_half(half - wall_margin, frame_yaw)
        for x in xs:
            for y in ys:
                world = receptacle.frame.apply(np.array([[x, y, 0.0]]))[0]
                if _clearance(world[:2], world_half + MARGIN, obstacles) < 0:
                    continue
                center = np.array([world[0], world[1], bottom + height / 2 + DROP])
                # Nearest the corner first; among equals, the smaller turn.
                if near_xy is None:
                    score = -float(np.abs(np.array([x, y]) - corner).sum()) - 0.01 * abs(turn)
                else:
                    score = -float(np.linalg.norm(world[:2] - near_xy)) - 0.01 * abs(turn)
                out.append(PlacementSpot(center, turn, score))
    out.sort(key=lambda s: -s.score)
    return out


def fits(receptacle: Receptacle, half_xy: np.ndarray) -> bool:
    """Whether a footprint of half-extents ``half_xy`` fits the empty interior at all (in some quarter turn)."""
    inner = receptacle.upper[:2] - receptacle.lower[:2] - 2 * MARGIN
    size = 2 * np.asarray(half_xy)
    return bool(np.all(size <= inner + 1e-9) or np.all(size[::-1] <= inner + 1e-9))


def spot_at(position: np.ndarray, object_size: np.ndarray, support_top: float) -> PlacementSpot:
    """The object centred at ``position``; never lower than resting on the support beneath it."""
    rest = support_top + object_size[2] / 2 + DROP
    center = np.array([position[0], position[1], max(float(position[2]), rest)])
    return PlacementSpot(center, 0.0, 0.0)
