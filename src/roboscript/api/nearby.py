"""Free spots near a position a program chose (geometry only): the position itself where it is free, else the
nearest spots around it, ring by ring, that lie on its support and clear of everything else.

A program picks a position from what it can see (the middle of where something was, a spot 15 cm beside a box);
the spot may be taken by a neighbour's edge, lie a little off the plate it means, or stand just out of the arm's
reach. A careful person would put the thing down a few centimetres away: the nearest free spot within
:data:`NEAREST_BOUND` stands in for it, and the placement search (:mod:`roboscript.api.placement`) tries them in
order of distance until the arm reaches one.

A position is usually chosen by what is near it ("15 cm beside the red mug"), and a position does not say which
neighbour it was chosen by. So among spots about as near, those that keep the position's near neighbours as near
come first: the thing moves along its neighbours, not away from them (:func:`keeping_neighbours`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from roboscript.api.spots import DROP, MARGIN, Footprint, PlacementSpot, gaps
from roboscript.perception.base import Receptacle

NEAREST_BOUND = 0.15  # metres a program's position may move to the nearest free, reachable spot
REPORT_BOUND = 0.30  # metres searched, beyond NEAREST_BOUND, only to say in an error how far a free spot was
RING_STEP = 0.02  # metres between the rings of candidates round the position
RING_POINTS = 8  # candidates on the first ring; further rings have as many as keep them RING_STEP apart
MOVED = 0.005  # metres: a spot this near the position is the position (no notice)
REACH_MIDDLE = 0.5  # metres from the base: among equally near spots, those nearer this come first
TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)
# Neighbours whose footprints stood this near the asked-for one, or overlapped it by no more than NEIGHBOUR_OVERLAP,
# are those the position was chosen by: a moved spot is charged NEIGHBOUR_WEIGHT times each centimetre it takes the
# thing further from them than asked (from one it overlapped: than touching it). The benchmark's "near" allows 8 cm
# between footprints. Moving along a neighbour keeps the relation the program asked for; moving away from it breaks
# it, so that counts for more than the distance moved. A slight overlap is a neighbour misjudged (a program that put
# a mug "3 cm beside" another's box overlaps it by the handle turned its way); a deep one is what stands in the way,
# which the program did not know of, and a spot snug against that leaves no room for fingers to take the thing again.
NEIGHBOUR_GAP = 0.05
NEIGHBOUR_OVERLAP = 0.03
NEIGHBOUR_WEIGHT = 2.0


@dataclass(frozen=True)
class Support:
    """What a held object set down at a position rests on: a receptacle's free volume (a bowl's interior, a
    box's top, the table's top), the height of its floor in the world, and the footprints it must keep clear of."""

    region: Receptacle
    floor: float
    obstacles: tuple[Footprint, ...]


def ring_candidates(target_xy: np.ndarray, bound: float, base_xy: np.ndarray) -> np.ndarray:
    """Points ``(N, 2)`` round ``target_xy`` within ``bound``: the target first, then ring after ring outwards;
    within a ring, those nearer the middle of the arm's reach first."""
    points = [np.asarray(target_xy, dtype=float)[None]]
    radius = RING_STEP
    while radius <= bound + 1e-9:
        count = max(RING_POINTS, math.ceil(2 * math.pi * radius / RING_STEP))
        angles = np.arange(count) * 2 * math.pi / count
        ring = target_xy + radius * np.column_stack([np.cos(angles), np.sin(angles)])
        order = np.argsort(np.abs(np.linalg.norm(ring - base_xy, axis=1) - REACH_MIDDLE), kind="stable")
        points.append(ring[order])
        radius += RING_STEP
    return np.vstack(points)


def free_spots(
    candidates: np.ndarray, half: np.ndarray, yaw: float, height: float, support: Support
) -> list[PlacementSpot]:
    """The candidates where the object (footprint half-extents ``half``, turned ``yaw``) fits on ``support`` in
    some quarter turn: its footprint within the support's region (or, for an object larger than the region, its
    middle over it) and clear of the support's obstacles. Each spot keeps the turns that fit, in candidate order."""
    region = support.region
    inverse = region.frame.inverse()
    local = inverse.apply(np.column_stack([candidates, np.full(len(candidates), support.floor)]))[:, :2]
    frame_yaw = math.atan2(region.frame.rotation[1, 0], region.frame.rotation[0, 0])
    lower, upper = region.lower[:2], region.upper[:2]
    fitting = np.zeros((len(candidates), len(TURNS)), dtype=bool)
    for k, turn in enumerate(TURNS):
        own_half = np.asarray(half) + MARGIN
        corners = Footprint(np.zeros(2), yaw + turn - frame_yaw, own_half).corners()
        extent = np.abs(corners).max(axis=0)
        # An object wider than its support's top (a block on a can) need only have its middle over it.
        room = lower + extent <= upper - extent + 1e-9
        lo, hi = np.where(room, lower + extent, lower), np.where(room, upper - extent, upper)
        ok = np.all((local >= lo - 1e-9) & (local <= hi + 1e-9), axis=1)
        for obstacle in support.obstacles:
            ok &= gaps(candidates, yaw + turn, own_half, obstacle) >= 0
        fitting[:, k] = ok
    spots = []
    for index in np.flatnonzero(fitting.any(axis=1)):
        turns = tuple(t for t, fit in zip(TURNS, fitting[index], strict=True) if fit)
        center = np.array([*candidates[index], support.floor + height / 2 + DROP])
        spots.append(PlacementSpot(center, 0.0, -float(index), turns=turns))
    return spots


def distance_moved(spot: PlacementSpot, target: np.ndarray) -> float:
    """How far, in x and y, a spot is from the position a program asked for."""
    return float(np.linalg.norm(spot.center[:2] - np.asarray(target, dtype=float)[:2]))


def keeping_neighbours(
    spots: list[PlacementSpot], target_xy: np.ndarray, half: np.ndarray, yaw: float, obstacles: tuple[Footprint, ...]
) -> list[PlacementSpot]:
    """The spots round ``target_xy`` reordered: by how far each moves the thing plus (twice) how much further it
    takes it from the target's neighbours (footprints within :data:`NEIGHBOUR_GAP` of the thing's footprint at the
    target, or overlapping it by at most :data:`NEIGHBOUR_OVERLAP`), in steps of :data:`RING_STEP` so that within
    a step the ring's order (nearest the middle of the reach first) stands."""
    if not spots:
        return spots
    own_half = np.asarray(half, dtype=float) + MARGIN
    target = np.asarray(target_xy, dtype=float)[None]
    centers = np.array([s.center[:2] for s in spots])
    cost = np.linalg.norm(centers - target, axis=1)
    for obstacle in obstacles:
        asked = float(gaps(target, yaw, own_half, obstacle)[0])
        if -NEIGHBOUR_OVERLAP <= asked <= NEIGHBOUR_GAP:
            cost += NEIGHBOUR_WEIGHT * np.clip(gaps(centers, yaw, own_half, obstacle) - max(asked, 0.0), 0.0, None)
    steps = np.round(cost / RING_STEP).astype(int)
    order = np.argsort(steps, kind="stable")
    return [spots[k] for k in order]
