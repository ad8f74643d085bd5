"""Putting things into the compartment behind a cabinet door: a shelf under a shelf, reached from the front.

A hand cannot come down into a compartment from above (the panel above it is in the way): it carries the object in
through the open door with its fingers level, and backs out the way it came. So the object must be held from the
side (``parse_horizontal_grasp_pose``); the hand is turned about the vertical until it points into the compartment,
and the spots nearest the front come first (the arm reaches in least).
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.api.spots import DROP, MARGIN, Footprint, PlacementSpot, gaps
from roboscript.errors import FailureError
from roboscript.geometry import Transform
from roboscript.perception.base import Receptacle

LEVEL_ENOUGH = 0.85  # cosine: a hand pointing down steeper than ~58 degrees holds the object from above
TURNS = (0.0, math.radians(15), -math.radians(15))  # the hand's turns about the vertical tried at each spot
WALL_MARGIN = 0.02  # kept from the compartment's walls: a held object may swing a little in the fingers
STEP = 0.02  # metres between spots


class CompartmentError(FailureError, RuntimeError):
    """The held object cannot go into a compartment the way it is held, or the door is closed."""


def open_side(receptacle: Receptacle) -> np.ndarray:
    """The horizontal direction out of the compartment's front (its cabinet's +x)."""
    out = receptacle.frame.rotation[:, 0].copy()
    out[2] = 0.0
    return out / max(float(np.linalg.norm(out)), 1e-9)


def hand_turn(tcp: Transform, receptacle: Receptacle, held: str) -> float:
    """The turn (radians, about the vertical) that points the hand at ``tcp`` level into the compartment; a
    :class:`CompartmentError` where it holds ``held`` from above."""
    approach = tcp.rotation[:, 2]
    if float(approach[2]) < -LEVEL_ENOUGH or float(np.linalg.norm(approach[:2])) < 1e-3:
        raise CompartmentError(
            f"{held!r} is held from above, and things go into {receptacle.name!r} from its front, under the panel "
            f"above it: it must be held level, taken with parse_horizontal_grasp_pose (where no level grasp reaches "
            f"it among its neighbours, that tool says so in a notice and grasps it from above: set it down in the "
            f"open first, then take it level)"
        )
    inward = -open_side(receptacle)
    return math.remainder(math.atan2(inward[1], inward[0]) - math.atan2(approach[1], approach[0]), 2 * math.pi)


def compartment_spots(
    receptacle: Receptacle,
    footprint: Footprint,
    height: float,
    turn: float,
    obstacles: list[Footprint],
    base_xy: np.ndarray,
) -> list[PlacementSpot]:
    """Free spots in the compartment for an object whose footprint is ``footprint`` now, once the hand has turned
    it by ``turn``: clear of the walls by :data:`WALL_MARGIN` in any of :data:`TURNS` and of what is in there;
    nearest the front first, then nearest the robot's side."""
    lower, upper = receptacle.lower, receptacle.upper
    frame_yaw = math.atan2(receptacle.frame.rotation[1, 0], receptacle.frame.rotation[0, 0])
    half = np.zeros(2)
    for extra in TURNS:
        relative = footprint.yaw + turn + extra - frame_yaw
        c, s = abs(math.cos(relative)), abs(math.sin(relative))
        h = footprint.half
        turned = np.array([c * h[0] + s * h[1], s * h[0] + c * h[1]])
        half = np.maximum(half, turned)
    lo, hi = lower[:2] + half + WALL_MARGIN, upper[:2] - half - WALL_MARGIN
    if np.any(hi < lo) or upper[2] - lower[2] < height + DROP:
        return []
    xs = np.arange(hi[0], lo[0] - 1e-9, -STEP)
    ys = np.arange(lo[1], hi[1] + 1e-9, STEP) if hi[1] - lo[1] > STEP else np.array([(lo[1] + hi[1]) / 2])
    grid = np.array([[x, y] for x in xs for y in ys])
    bottom = float(receptacle.frame.apply(np.array([[0.0, 0.0, lower[2]]]))[0, 2])
    world = receptacle.frame.apply(np.column_stack([grid, np.zeros(len(grid))]))[:, :2]
    free = np.ones(len(grid), dtype=bool)
    for other in obstacles:
        free &= gaps(world, frame_yaw, half + MARGIN, other) >= 0
    side = world - np.asarray(base_xy)
    spots = []
    for k in np.flatnonzero(free):
        depth = float(hi[0] - grid[k, 0])
        score = -depth - 0.1 * float(np.linalg.norm(side[k]))
        center = np.array([world[k, 0], world[k, 1], bottom + height / 2 + DROP])
        spots.append(PlacementSpot(center, turn, score, TURNS, open_side(receptacle)))
    spots.sort(key=lambda s: -s.score)
    return spots
