"""Free spots for a held object: inside a receptacle, on the table, or at a given position (geometry only).

Candidates are object positions (the middle of the object's footprint, at its box's height) with a yaw turn; the
placement search (:mod:`roboscript.api.placement`) turns them into gripper poses and keeps the first one the arm
can reach. A spot is free when the
object's footprint, with a margin, stays inside the receptacle's interior and clear of every other object's
footprint. Footprints are turned rectangles: a banana lying at 30 degrees covers a strip of a plate, while its
world-aligned box would cover most of it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.base import Receptacle
from roboscript.perception.footprints import rectangle_outline

MARGIN = 0.007  # clearance kept from walls and from other objects
DROP = 0.012  # the object is released this far above its support
# Score lost per metre a spot stands beyond a round floor: more than any corner distance gains (spots within it come
# first), and among spots beyond it the least beyond comes first (a banana longer than a plate's flat middle).
OVERHANG_WEIGHT = 100.0


_SIGNS = np.array([[1, 1], [1, -1], [-1, 1], [-1, -1]])  # a rectangle's corners, in half-extents


@dataclass(frozen=True)
class Footprint:
    """A rectangle on the table: centre (x, y), turned by ``yaw`` radians, with half-extents along its own axes."""

    center: np.ndarray
    yaw: float
    half: np.ndarray
    # Its outline from above (K, 2: corners in order round it, in the world) where it is known to be other than
    # the rectangle (a mug's circle and handle): how far things are from it is measured to this.
    outline: np.ndarray | None = field(default=None, compare=False)

    @staticmethod
    def of_box(box: Box3D) -> Footprint:
        return Footprint(box.center[:2], 0.0, box.size[:2] / 2)

    def shape(self) -> np.ndarray:
        """Its outline from above, else its rectangle's corners in order round it."""
        if self.outline is None:
            return rectangle_outline(self.center, self.yaw, self.half)
        return np.asarray(self.outline, dtype=float)

    def axes(self) -> np.ndarray:
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return np.array([[c, s], [-s, c]])

    def corners(self) -> np.ndarray:
        return np.asarray(self.center) + (_SIGNS * self.half) @ self.axes()


def gap(a: Footprint, b: Footprint) -> float:
    """How far apart two footprints are along the axis that separates them best (negative: they overlap)."""
    return float(gaps(a.center[None], a.yaw, a.half, b)[0])


def gaps(centers: np.ndarray, yaw: float, half: np.ndarray, other: Footprint) -> np.ndarray:
    """:func:`gap` from each of several footprints alike but for their centres ``(N, 2)`` to ``other``."""
    axes_a = Footprint(np.zeros(2), yaw, half).axes()
    corners_a = np.asarray(centers)[:, None, :] + ((_SIGNS * half) @ axes_a)[None]  # (N, 4, 2)
    corners_b = other.corners()
    best = np.full(len(centers), -np.inf)
    for axis in np.vstack([axes_a, other.axes()]):
        pa, pb = corners_a @ axis, corners_b @ axis
        best = np.maximum(best, np.maximum(pb.min() - pa.max(axis=1), pa.min(axis=1) - pb.max()))
    return best


def outline_distances(centers: np.ndarray, outline: np.ndarray, other: np.ndarray) -> np.ndarray:
    """How far apart, as the crow flies, the convex outline ``outline`` (M, 2: its corners in order round it,
    relative to its centre) put at each of ``centers`` (N, 2) is from the convex outline ``other`` (K, 2, in the
    world): the shortest distance between them where they are apart, else how deep they overlap (negative, along
    the axis that separates them best). A mug's outline is a circle and its handle: the rectangle round it has
    corners a few centimetres out, and two rectangles apart corner to corner are nearer along their best
    separating axis than the distance a reader sees between the things."""
    centers = np.asarray(centers, dtype=float)
    local, other = np.asarray(outline, dtype=float), np.asarray(other, dtype=float)
    separation = np.full(len(centers), -np.inf)
    for axis in np.vstack([_edge_normals(local), _edge_normals(other)]):
        own, theirs, shift = local @ axis, other @ axis, centers @ axis
        apart_along = np.maximum(theirs.min() - (shift + own.max()), shift + own.min() - theirs.max())
        separation = np.maximum(separation, apart_along)
    placed = centers[:, None, :] + local[None]  # (N, M, 2)
    fixed = np.broadcast_to(other, (len(centers), *other.shape))
    apart = np.minimum(_corners_to_edges(placed, fixed), _corners_to_edges(fixed, placed))
    return np.where(separation > 0, apart, separation)


def stands_clear(
    centers: np.ndarray,
    yaw: float,
    own_half: np.ndarray,
    obstacle: Footprint,
    outline: np.ndarray | None = None,
    among: np.ndarray | None = None,
) -> np.ndarray:
    """Whether a footprint (half-extents ``own_half``, the margin included, turned ``yaw``) at each of ``centers``
    (N, 2) stands clear of ``obstacle``. With the thing's ``outline`` (K, 2, turned as the footprint, relative to
    its middle) and the obstacle's, where the rectangles meet the outlines decide: :data:`MARGIN` apart is clear.
    ``among``: only these centres (a mask) need the outlines' test; the rest keep the rectangles' answer."""
    clear = gaps(centers, yaw, own_half, obstacle) >= 0
    if outline is None or obstacle.outline is None:
        return clear
    closer = np.flatnonzero(~clear if among is None else ~clear & among)
    if len(closer):  # the rectangles hold the outlines: only where they meet need the outlines be measured
        clear[closer] = outline_distances(np.asarray(centers)[closer], outline, obstacle.shape()) >= MARGIN
    return clear


def turned(outline: np.ndarray, angle: float) -> np.ndarray:
    """``outline`` (K, 2) turned ``angle`` radians about its origin."""
    c, s = math.cos(angle), math.sin(angle)
    return np.asarray(outline, dtype=float) @ np.array([[c, s], [-s, c]])


def _edge_normals(outline: np.ndarray) -> np.ndarray:
    edges = np.roll(outline, -1, axis=0) - outline
    normals = np.column_stack([-edges[:, 1], edges[:, 0]])
    lengths = np.linalg.norm(normals, axis=1)
    return normals[lengths > 1e-9] / lengths[lengths > 1e-9, None]


def _corners_to_edges(corners: np.ndarray, outline: np.ndarray) -> np.ndarray:
    """The shortest distance from any of ``corners`` (N, M, 2) to the edges of the closed ``outline`` (N, K, 2)."""
    start, end = outline, np.roll(outline, -1, axis=1)
    edge = (end - start)[:, None]  # (N, 1, K, 2): every corner against every edge
    offset = corners[:, :, None] - start[:, None]
    along = np.clip(np.sum(offset * edge, axis=-1) / np.maximum(np.sum(edge * edge, axis=-1), 1e-12), 0.0, 1.0)
    return np.linalg.norm(offset - along[..., None] * edge, axis=-1).min(axis=(1, 2))


@dataclass(frozen=True)
class PlacementSpot:
    """Where the middle of the object's footprint goes (its box's middle in height), and the yaw turn (radians)
    about world z from its present pose; ``score`` orders spots (higher first). ``turns``: further turns about z
    the object may be given there (a spot at a position does not care how the object faces; one squared to a
    receptacle may only be turned round). ``open_side``: the horizontal direction in which nothing stands over
    the spot (out of a drawer, beneath the one above it), where the hand may lean if it cannot reach the spot
    upright; None: toward the robot."""

    center: np.ndarray
    yaw: float
    score: float
    turns: tuple[float, ...] = (0.0, math.pi)
    open_side: np.ndarray | None = None


def spots_in_receptacle(
    receptacle: Receptacle,
    half_xy: np.ndarray,
    object_yaw: float,
    height: float,
    obstacles: list[Footprint],
    corner_xy: np.ndarray,
    step: float = 0.015,
    near_xy: np.ndarray | None = None,
    wall_margin: float = MARGIN,
    outline: np.ndarray | None = None,
) -> list[PlacementSpot]:
    """Free spots inside the receptacle's interior, filled from the corner nearest ``corner_xy`` outwards.

    The object (footprint half-extents ``half_xy`` in its own frame, turned by ``object_yaw``) is turned square to
    the receptacle in each of four ways. Filling from one corner, like packing a box, leaves the most room for
    what comes next; the corner nearest the robot keeps the arm's reach short. With ``near_xy`` (putting
    something aside on the table) the spots nearest that point come first instead. With the object's ``outline``
    (K, 2, relative to its footprint's middle), what it must keep clear of is measured outline to outline
    (:func:`stands_clear`): a banana's rectangle covers much of a round plate, the banana does not.
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
        own_half = (half_xy if quarter % 2 == 0 else half_xy[::-1]) + MARGIN
        grid = np.array([[x, y] for x in xs for y in ys])
        world = receptacle.frame.apply(np.column_stack([grid, np.zeros(len(grid))]))
        free = np.ones(len(grid), dtype=bool)
        own = None if outline is None else turned(outline, turn)
        for o in obstacles:
            free &= stands_clear(world[:, :2], frame_yaw, own_half, o, own, free)
        shape = _SIGNS * (half - wall_margin) if own is None else turned(own, -frame_yaw)
        beyond = overhang(receptacle, grid, shape, wall_margin)
        for k in np.flatnonzero(free):
            center = np.array([world[k, 0], world[k, 1], bottom + height / 2 + DROP])
            # Within a round floor first, then the least beyond it; nearest the corner next; then the smaller turn.
            if near_xy is None:
                score = -float(np.abs(grid[k] - corner).sum()) - 0.01 * abs(turn)
            else:
                score = -float(np.linalg.norm(world[k, :2] - near_xy)) - 0.01 * abs(turn)
            out.append(PlacementSpot(center, turn, score - OVERHANG_WEIGHT * float(beyond[k])))
    out.sort(key=lambda s: -s.score)
    return out


def overhang(receptacle: Receptacle, spots: np.ndarray, shape: np.ndarray, margin: float = MARGIN) -> np.ndarray:
    """How far (metres) a thing of outline ``shape`` (K, 2, in the receptacle's frame, relative to its middle)
    stands beyond a round floor (:attr:`Receptacle.round_floor`, less ``margin``) at each of ``spots`` (N, 2, in
    the receptacle's frame): 0 within it, and for every receptacle without a round floor. A bottle in the corner of
    the box round a plate's flat middle stands on the rim and falls over when let go."""
    spots = np.asarray(spots, dtype=float)
    if not receptacle.round_floor:
        return np.zeros(len(spots))
    middle = (receptacle.lower[:2] + receptacle.upper[:2]) / 2
    axes = np.maximum((receptacle.upper[:2] - receptacle.lower[:2]) / 2 - margin, 1e-3)
    placed = spots[:, None, :] + np.asarray(shape, dtype=float)[None] - middle  # (N, K, 2)
    reach = np.linalg.norm(placed / axes, axis=-1).max(axis=1)
    return np.maximum(reach - 1.0, 0.0) * float(axes.min())


def fits(receptacle: Receptacle, half_xy: np.ndarray) -> bool:
    """Whether a footprint of half-extents ``half_xy`` fits the empty interior at all (in some quarter turn)."""
    inner = receptacle.upper[:2] - receptacle.lower[:2] - 2 * MARGIN
    size = 2 * np.asarray(half_xy)
    return bool(np.all(size <= inner + 1e-9) or np.all(size[::-1] <= inner + 1e-9))
