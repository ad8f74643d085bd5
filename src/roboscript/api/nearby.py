"""Free spots near a position a program chose (geometry only): the position itself where it is free, else the
nearest spots around it, ring by ring, that lie on its support and clear of everything else (of what each thing
covers from above, its outline, not only of the rectangle round it: a round thing's rectangle has corners the thing
does not).

A program picks a position from what it can see (the middle of where something was, a spot 15 cm beside a box);
the spot may be taken by a neighbour's edge, lie a little off the plate it means, or stand just out of the arm's
reach. A careful person would put the thing down a few centimetres away: the nearest free spot within
:data:`NEAREST_BOUND` stands in for it, and the placement search (:mod:`roboscript.api.placement`) tries them in
order of distance until the arm reaches one.

A position is usually chosen by what is near it ("15 cm beside the red mug"), and a position does not say which
neighbour it was chosen by. So among spots about as near, those that keep the position's near neighbours as near
come first: the thing moves along its neighbours, not away from them; and a moved spot that leaves the fingers
room to take the thing again comes before one snug against what stood in the way (:func:`ranked`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from roboscript.api.spots import DROP, MARGIN, Footprint, PlacementSpot, gaps, outline_distances, stands_clear, turned
from roboscript.perception.base import Receptacle

NEAREST_BOUND = 0.15  # metres a program's position may move to the nearest free, reachable spot
REPORT_BOUND = 0.30  # metres searched, beyond NEAREST_BOUND, only to say in an error how far a free spot was
RING_STEP = 0.02  # metres between the rings of candidates round the position
RING_POINTS = 8  # candidates on the first ring; further rings have as many as keep them RING_STEP apart
MOVED = 0.005  # metres: a spot this near the position is the position (no notice)
REACH_MIDDLE = 0.5  # metres from the base: among equally near spots, those nearer this come first
TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)
# Neighbours whose outlines stood this near the asked-for one, or overlapped it by no more than NEIGHBOUR_OVERLAP,
# are those the position was chosen by: a moved spot is charged NEIGHBOUR_WEIGHT times each centimetre it takes the
# thing further from them than asked (from one it overlapped: than a finger's room). Things 8 cm apart stand beside
# each other to a reader (the benchmark's "near" allows as much); a mug put 5.5 cm from another, measured as the
# crow flies between their outlines, is beside it. Moving along a neighbour keeps the relation the program asked
# for; moving away from it breaks it, so that counts for more than the distance moved. A slight overlap is a
# neighbour misjudged (a program that put a mug "3 cm beside" another's box overlaps it by the handle turned its
# way); a deep one is what stands in the way, which the program did not know of, and a spot snug against that
# leaves no room for fingers to take the thing again.
NEIGHBOUR_GAP = 0.08
NEIGHBOUR_OVERLAP = 0.03
NEIGHBOUR_WEIGHT = 2.0
# A thing moved is often taken again (a swap sets it aside, then fetches it): a moved spot should leave room, on both
# sides of a line across its footprint that the fingers close along, for the open fingers coming down round it. A
# gelatin box moved 6 cm against a medication bottle (5 mm between them) could not be grasped again. Spots without
# that room in any turn are charged FINGER_PENALTY metres; those with it keep only the turns that have it.
FINGER_ROOM = 0.03
FINGER_PENALTY = 0.04
# A thing sent away from where it was taken is not brought back: each centimetre a moved spot is nearer that place
# than the position asked for counts once more (a toy car sent 20 cm towards the robot, onto a saucer, came back 14
# cm towards its old place, beside the saucer, where a swap's next object was to go).
ORIGIN_WEIGHT = 1.0
ORIGIN_RADIUS = 0.2  # metres round that place within which a moved spot counts as brought back
SQUARE_RATIO = 1.1  # a footprint whose sides differ by less than this (a can, a cube) is taken across either side
# Nearer than this to the base's axis the Panda's wrist works at its joint limits: from a grasp from above at the
# table's height it lifts a thing 3-8 cm of 10 at 12-16 cm from the axis, the full 10 cm from 20 cm on, and the
# carry that follows swings round behind the base (a pear set down 12 cm from it fell out of the fingers). A thing
# put down is often taken again, so spots this near the base come after every spot beyond.
NEAR_BASE = 0.2


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
    candidates: np.ndarray,
    half: np.ndarray,
    yaw: float,
    height: float,
    support: Support,
    outline: np.ndarray | None = None,
) -> list[PlacementSpot]:
    """The candidates where the object (footprint half-extents ``half``, turned ``yaw``) fits on ``support`` in
    some quarter turn: its footprint within the support's region (or, for an object larger than the region, its
    middle over it) and clear of the support's obstacles. Each spot keeps the turns that fit, in candidate order.
    With the object's ``outline`` (K, 2, relative to its footprint's middle), clear means its outline stays
    :data:`MARGIN` from theirs: a mug's rectangle overlaps a strawberry's where the mug itself stands clear of it."""
    region = support.region
    inverse = region.frame.inverse()
    local = inverse.apply(np.column_stack([candidates, np.full(len(candidates), support.floor)]))[:, :2]
    frame_yaw = math.atan2(region.frame.rotation[1, 0], region.frame.rotation[0, 0])
    lower, upper = region.lower[:2], region.upper[:2]
    fitting = np.zeros((len(candidates), len(TURNS)), dtype=bool)
    for k, turn in enumerate(TURNS):
        own_half = np.asarray(half) + MARGIN
        own = None if outline is None else turned(outline, turn)
        if own is None:
            reach = Footprint(np.zeros(2), yaw + turn - frame_yaw, own_half).corners()
        else:
            # The outline stays within the region, not the turned rectangle round it: an apple's square, turned
            # 22 degrees to a basket's sides, reaches 1.4 cm further each way than the apple does.
            shape = turned(own, -frame_yaw)
            reach = np.vstack([shape.min(axis=0) - MARGIN, shape.max(axis=0) + MARGIN])
        low, high = lower - reach.min(axis=0), upper - reach.max(axis=0)
        # An object wider than its support's top (a block on a can) need only have its middle over it.
        room = low <= high + 1e-9
        lo, hi = np.where(room, low, lower), np.where(room, high, upper)
        ok = np.all((local >= lo - 1e-9) & (local <= hi + 1e-9), axis=1)
        for obstacle in support.obstacles:
            ok &= stands_clear(candidates, yaw + turn, own_half, obstacle, own, ok)
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


def ranked(
    spots: list[PlacementSpot],
    target_xy: np.ndarray,
    half: np.ndarray,
    yaw: float,
    obstacles: tuple[Footprint, ...],
    origin_xy: np.ndarray | None = None,
    outline: np.ndarray | None = None,
) -> list[PlacementSpot]:
    """The spots round ``target_xy`` reordered: by how far each moves the thing, plus (twice) how much further it
    takes it from the target's neighbours (outlines within :data:`NEIGHBOUR_GAP` of the thing's outline at the
    target, or overlapping it by at most :data:`NEIGHBOUR_OVERLAP`), plus :data:`FINGER_PENALTY` for a moved spot
    that leaves no finger room (:func:`finger_room_turns`), plus how much nearer a moved spot is than the target
    to ``origin_xy``, where the thing was taken (:data:`ORIGIN_WEIGHT`), in steps of :data:`RING_STEP` so that
    within a step the ring's order (nearest the middle of the reach first) stands. A moved spot with finger room
    keeps only the turns that leave it. ``outline``: the thing's outline from above (K, 2) relative to its
    footprint's middle (else its rectangle, turned ``yaw``); distances to neighbours are between outlines, as the
    crow flies (:func:`outline_distances`), in the turn that keeps each nearest."""
    if not spots:
        return spots
    own = Footprint(np.zeros(2), yaw, np.asarray(half, dtype=float)).shape() if outline is None else outline
    target = np.asarray(target_xy, dtype=float)[None]
    asked = [float(outline_distances(target, own, obstacle.shape())[0]) for obstacle in obstacles]
    # One the position overlapped is kept beside, with a finger's room: whoever misjudged it meant the thing to
    # stand next to it, and a thing snug against it cannot be taken again.
    neighbours = [
        (o, a if a >= 0.0 else FINGER_ROOM)
        for o, a in zip(obstacles, asked, strict=True)
        if -NEIGHBOUR_OVERLAP <= a <= NEIGHBOUR_GAP
    ]
    # Only coming back near the old place counts: not the front of a drawer the thing was carried to.
    sent = None if origin_xy is None else min(float(np.linalg.norm(target[0] - origin_xy)), ORIGIN_RADIUS)
    kept, costs = [], []
    for spot in spots:
        moved = float(np.linalg.norm(spot.center[:2] - target[0]))
        cost = moved
        if moved > MOVED:  # the position itself stays as the program chose it
            roomy = finger_room_turns(spot, half, yaw, obstacles)
            spot = replace(spot, turns=roomy) if roomy else spot
            cost += 0.0 if roomy else FINGER_PENALTY
            if sent is not None:
                cost += ORIGIN_WEIGHT * max(sent - float(np.linalg.norm(spot.center[:2] - origin_xy)), 0.0)
        kept.append(spot)
        costs.append(cost)
    costs = np.array(costs) + NEIGHBOUR_WEIGHT * _drift_from(kept, own, neighbours)
    steps = np.round(costs / RING_STEP).astype(int)
    return [kept[k] for k in np.argsort(steps, kind="stable")]


def _drift_from(spots: list[PlacementSpot], own: np.ndarray, neighbours: list[tuple[Footprint, float]]) -> np.ndarray:
    """Per spot, how much further in all the thing (outline ``own``, relative to its middle) stands from its
    ``neighbours`` than the distance each had, in the spot's turn that keeps it nearest each."""
    drift = np.zeros(len(spots))
    if not neighbours:
        return drift
    centers = np.array([spot.center[:2] for spot in spots])
    turns = sorted({turn for spot in spots for turn in spot.turns})
    allowed = np.array([[turn in spot.turns for turn in turns] for spot in spots])
    for neighbour, had in neighbours:
        shape = neighbour.shape()
        apart = np.column_stack([outline_distances(centers, turned(own, t), shape) for t in turns])
        drift += np.maximum(np.where(allowed, apart, np.inf).min(axis=1) - had, 0.0)
    return drift


def near_base(xy: np.ndarray, base_xy: np.ndarray) -> bool:
    """Whether ``xy`` lies within :data:`NEAR_BASE` of the base's axis at ``base_xy``."""
    return float(np.linalg.norm(np.asarray(xy, dtype=float)[:2] - np.asarray(base_xy, dtype=float))) < NEAR_BASE


def clear_of_base(spots: list[PlacementSpot], base_xy: np.ndarray) -> list[PlacementSpot]:
    """``spots`` in order, those :func:`near_base` moved after the rest."""
    return sorted(spots, key=lambda spot: near_base(spot.center, base_xy))  # stable: the order stands within each


def finger_room_turns(
    spot: PlacementSpot, half: np.ndarray, yaw: float, obstacles: tuple[Footprint, ...]
) -> tuple[float, ...]:
    """The turns of ``spot`` in which the thing (footprint half-extents ``half``, turned ``yaw``) has
    :data:`FINGER_ROOM` clear on both sides along a side the fingers would close across: the narrower, or either
    of a footprint about square (:data:`SQUARE_RATIO`)."""
    half = np.asarray(half, dtype=float)
    own_half = half + MARGIN
    across = [k for k in (0, 1) if half[k] <= SQUARE_RATIO * half.min()]
    center = spot.center[None, :2]
    roomy = []
    for turn in spot.turns:
        for k in across:
            grown = own_half.copy()
            grown[k] += FINGER_ROOM
            if all(gaps(center, yaw + turn, grown, obstacle)[0] >= 0 for obstacle in obstacles):
                roomy.append(turn)
                break
    return tuple(roomy)
