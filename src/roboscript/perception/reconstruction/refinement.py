"""Refinement of 3D instances from the depth pixels themselves: each instance's points taken again from the pixels
of its 2D boxes that lie in its fused box, given up to the smaller instances refined before it, cut to the largest
connected piece and its skirt (the flat support beside its foot) trimmed. The fused surface finds and separates
objects; its points stand a few millimetres proud of flat sides seen at a slant, which the depth pixels do not.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from typing import Protocol

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.base import within
from roboscript.perception.reconstruction.instances import (
    FOOTPRINT_HEIGHT,
    PIXEL_BLUR,
    Instance3D,
    largest_cluster,
    object_box,
)

SKIRT_BAND = 0.012  # metres above an object's lowest point within which a flat support beside it may show
SKIRT_BULK = 0.4  # the least share of an object's points over the band for them to outline it (not a knife's edge)
SKIRT_MARGIN = 0.005  # metres round the outline of an object's upper part within which its foot may reach
OUTLINE_TOLERANCE = 1e-12  # metres past an outline's edge that still count as inside it (rounding)
CLAIM_MARGIN = 0.005  # metres round a smaller instance's refined box within which a pixel's point is its own


class Surface(Protocol):
    """A view's depth pixels as points and normals, by image rectangle (:class:`~roboscript.perception.points.
    DepthSurface`)."""

    def within(self, box: tuple[int, int, int, int], stride: int = 1) -> tuple[np.ndarray, np.ndarray]: ...


def refine_all(
    instances: Sequence[Instance3D],
    detections: Sequence[Sequence],
    surfaces: Sequence[Surface],
    support: float,
    furniture: Collection[str] = (),
) -> list[Instance3D]:
    """:func:`refine_with_depth` of each instance, smallest (fused) box first. An object gives up to the smaller
    objects refined before it the points in their boxes (a basket's upright box holds the cube beside it; a
    plate's, the box lying on it), and keeps its largest piece less its skirt. Furniture and its parts (labelled one
    of ``furniture``) are refined as they are seen: a drawer's front stands in its carcass's box, a handle on a
    drawer's front, an open door shows in pieces round the arm, and how far a drawer or door stands out is measured
    from all of it.

    Smallest in space, not in the images: a block stacked on a box hides the box's top from every camera above,
    and the box's boxes in the images come out the smaller; refined first, the box took the block's sides, and the
    block stood 3 cm higher on it than it does."""
    sizes = [i.box.volume for i in instances]
    refined: dict[int, Instance3D] = {}
    for k in sorted(range(len(instances)), key=lambda k: sizes[k]):
        maps = (instances[k], detections, surfaces, support)
        if instances[k].label in furniture:
            refined[k] = refine_with_depth(*maps)
            continue
        smaller = [refined[j] for j in refined if sizes[j] < sizes[k] and refined[j].label not in furniture]
        refined[k] = refine_with_depth(*maps, smaller=smaller, own=True)
    return [refined[k] for k in range(len(instances))]


def refine_with_depth(
    instance: Instance3D,
    detections: Sequence[Sequence],
    surfaces: Sequence[Surface],
    support: float,
    smaller: Sequence[Instance3D] = (),
    own: bool = False,
    stride: int = 2,
    margin: float = 0.01,
    above: float = 0.002,
) -> Instance3D:
    """The instance's points taken again from the depth images themselves: in each view where it was found, the
    pixels of its 2D box whose points lie in its fused box (``margin`` larger) and ``above`` the table (depth
    pixels are sharp enough to follow a plate's edge down nearer the table than the fused surface).

    The fused surface finds and separates objects; its points stand a few millimetres proud of flat sides seen
    at a slant (the signed-distance blur), which is the difference between a box that fits a gripper and one
    that does not. The depth pixels have no such blur.

    A point in the box of one of the ``smaller`` instances (already refined) is that instance's, as
    :func:`build_instances` gives a point two objects claim to the smaller. With ``own`` (an object, not a piece of
    furniture), what is left keeps its largest connected piece (:func:`largest_cluster`: the edge of a neighbour
    inside the margin falls away) less its skirt (:func:`without_skirt`)."""
    lower, upper = instance.box.lower - margin, instance.box.upper + margin
    lower = np.array([lower[0], lower[1], max(lower[2], support + above)])
    points, normals = [], []
    for view, box_index in enumerate(instance.boxes):
        if box_index == -1:
            continue
        world, normal = surfaces[view].within(detections[view][box_index].box, stride)
        keep = np.all((world > lower) & (world < upper), axis=1) & np.isfinite(normal).all(axis=1)
        keep &= ~_claimed_by(smaller, world)
        points.append(world[keep])
        normals.append(normal[keep])
    if not points or sum(len(p) for p in points) < 30:
        return instance
    points, normals = np.concatenate(points), np.concatenate(normals)
    if own:
        piece = largest_cluster(points)
        if len(piece) < 30:
            return instance
        points, normals = points[piece], normals[piece]
        kept = without_skirt(points)
        points, normals = points[kept], normals[kept]
    box = object_box(points, support, PIXEL_BLUR if own else FOOTPRINT_HEIGHT)
    return Instance3D(instance.label, points, normals, box, instance.boxes)


def without_skirt(points: np.ndarray, band: float = SKIRT_BAND, margin: float = SKIRT_MARGIN) -> np.ndarray:
    """Indices of ``points`` less the skirt: points within ``band`` of the lowest (its first percentile) that stand
    more than ``margin`` out of the outline from above of the points over that band. A box lying on a plate takes in,
    from every view, the plate beside it; the plate is flat and low, the box stands above its own foot. A thing whose
    points all lie in the band (a plate), whose upper part outlines its foot (a bowl's rim), or whose points over the
    band are fewer than :data:`SKIRT_BULK` of them (a knife beside a box, the box's side in its margin) loses
    nothing."""
    from scipy.spatial import ConvexHull, QhullError

    low = points[:, 2] < np.percentile(points[:, 2], 1) + band
    upper = points[~low, :2]
    if len(upper) < max(30, SKIRT_BULK * len(points)) or not low.any():
        return np.arange(len(points))
    try:
        outline = ConvexHull(_grown_outline(upper, margin))
    except QhullError:  # the upper points stand in a line from above: no outline to speak of
        return np.arange(len(points))
    # Inside the grown outline: on the inner side of each of its edges (a tenth of the time of locating each point
    # in a triangulation of it, which was a sixth of a look).
    sides = points[:, :2] @ outline.equations[:, :2].T + outline.equations[:, 2]
    inside = np.all(sides <= OUTLINE_TOLERANCE, axis=1)
    return np.flatnonzero(~low | inside)


def _grown_outline(xy: np.ndarray, margin: float) -> np.ndarray:
    """The corners of ``xy``'s convex outline grown by ``margin`` every way (each corner moved out eight ways)."""
    from scipy.spatial import ConvexHull

    corners = xy[ConvexHull(xy).vertices]
    turns = np.linspace(0.0, 2 * np.pi, 8, endpoint=False)
    ways = margin * np.column_stack([np.cos(turns), np.sin(turns)])
    return (corners[:, None, :] + ways[None, :, :]).reshape(-1, 2)


def _claimed_by(others: Sequence[Instance3D], points: np.ndarray) -> np.ndarray:
    """Which of ``points`` lie in the box of one of ``others``, grown by :data:`CLAIM_MARGIN` sideways and up but
    not below its bottom (what it stands on keeps its floor round it: a plate's, round the box lying on it). A
    point with no depth (NaN) is nobody's. Boxes, not the others' points: an object's refined points miss
    the sides its cameras did not see, which a larger neighbour's cameras did (a plate kept a box's side as its
    own, and the fingers met it there)."""
    return claimed_by_boxes([other.box for other in others], points)


def claimed_by_boxes(boxes: Sequence[Box3D], points: np.ndarray) -> np.ndarray:
    """Which of ``points`` lie in one of ``boxes``, grown by :data:`CLAIM_MARGIN` sideways and up but not below
    its bottom (see :func:`_claimed_by`)."""
    claimed = np.zeros(len(points), dtype=bool)
    with np.errstate(invalid="ignore"):
        for box in boxes:
            lower = np.array([*(box.lower[:2] - CLAIM_MARGIN), box.lower[2]])
            claimed |= within(points, Box3D(lower, box.upper + CLAIM_MARGIN))
    return claimed
