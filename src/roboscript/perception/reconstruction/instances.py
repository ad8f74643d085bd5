"""3D instances from matched 2D boxes: the fused points each object's boxes agree on, and a 3D box fitted to them.

A point belongs to an object when it lies in the object's box in at least one view and no view that saw the
object contradicts it (sees the point, outside the object's box there): with several views this carves the
object's visual hull out of the fused surface. What remains of the table around the object's foot is cut off at
the table's height.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.reconstruction.matching import MatchedObject, Projection

SUPPORT_MARGIN = 0.004  # metres above the support plane that still count as the support


@dataclass(frozen=True)
class Instance3D:
    """An object found in 3D: its label, fused surface points with normals, box, and its box index per view."""

    label: str
    points: np.ndarray
    normals: np.ndarray
    box: Box3D
    boxes: tuple[int, ...]


def instance_mask(
    matched: MatchedObject, memberships: Sequence[Sequence[np.ndarray]], projections: Sequence[Projection]
) -> np.ndarray:
    """Which fused points belong to ``matched``: in one of its boxes, and outside none that sees them."""
    first = next(i for i in matched.boxes if i != -1)
    inside = np.zeros_like(memberships[matched.boxes.index(first)][first])
    contradicted = np.zeros_like(inside)
    for view, box in enumerate(matched.boxes):
        if box == -1:
            continue
        member = memberships[view][box]
        inside |= member
        contradicted |= projections[view].visible & ~member
    return inside & ~contradicted


def densest_layer(values: np.ndarray, thickness: float) -> tuple[float, float]:
    """``(lower, upper)`` bounds of the layer ``thickness`` thick holding the most of ``values``."""
    counts, edges = np.histogram(values, bins=np.arange(values.min(), values.max() + 2 * thickness, thickness))
    peak = int(np.argmax(counts))
    return float(edges[peak]), float(edges[peak + 1])


def support_height(points: np.ndarray, bin_size: float = 0.002) -> float:
    """Height of the scene's dominant horizontal surface (the table): the densest thin layer of points."""
    return densest_layer(points[:, 2], bin_size)[1]


TABLE_BAND = 0.006  # metres below the support's height within which points belong to its top
TABLE_MIN_POINTS = 50


def table_surface(points: np.ndarray, normals: np.ndarray, support: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The points (and normals) of the table's top: those of the support's layer whose normals stand upright.
    ``None`` when too few were seen to call it a table."""
    level = (points[:, 2] > support - TABLE_BAND) & (points[:, 2] < support + 0.002)
    top = level & (np.abs(normals[:, 2]) > 0.8)
    if top.sum() < TABLE_MIN_POINTS:
        return None
    return points[top], normals[top]


FOOTPRINT_HEIGHT = 0.015  # metres above the support below which the fused surface blurs into it
CLUSTER_GAP = 0.0125  # metres between points of one object (2.5 voxels of 5 mm)
PIECE_SHARE = 0.2  # a furniture part keeps every piece at least this share of its largest
PIXEL_BLUR = 0.004  # metres above the support within which depth pixels still show an object standing on it


def fit_box(points: np.ndarray, trim: float = 1.0) -> Box3D:
    """The axis-aligned box of ``points``, ``trim`` percent cut from each side per axis against stray points."""
    if len(points) == 0:
        raise ValueError("cannot fit a box to no points")
    lower = np.percentile(points, trim, axis=0)
    upper = np.percentile(points, 100 - trim, axis=0)
    return Box3D(lower, upper)


def footprint_points(points: np.ndarray, support: float) -> np.ndarray:
    """The points that show an object's outline from above: those clear of where the fused surface blurs into
    the table (if the object is tall enough to have such)."""
    if points[:, 2].max() - support < 2 * FOOTPRINT_HEIGHT:  # flat (a plate): its edge is all there is
        return points
    upper = points[points[:, 2] > support + FOOTPRINT_HEIGHT]
    return upper if len(upper) >= 0.3 * len(points) and len(upper) >= 10 else points


def object_box(points: np.ndarray, support: float, blur: float = FOOTPRINT_HEIGHT) -> Box3D:
    """An object's box: its outline from :func:`footprint_points`, its height from all its points, down to the
    table when its lowest point is within ``blur`` of it (the fused surface never shows the face an object
    stands on, and blurs into the table that far; depth pixels hardly do)."""
    outline = fit_box(footprint_points(points, support), trim=0.5)
    heights = fit_box(points, trim=0.5)
    bottom = support if heights.lower[2] - support < blur else heights.lower[2]
    return Box3D(
        np.array([outline.lower[0], outline.lower[1], bottom]),
        np.array([outline.upper[0], outline.upper[1], heights.upper[2]]),
    )


def largest_cluster(points: np.ndarray, gap: float = CLUSTER_GAP, share: float = 1.0) -> np.ndarray:
    """Indices of the largest group of points connected by steps of at most ``gap`` (stray bits of the
    neighbours' surfaces fall away); with ``share`` below 1, also of every group at least that share of its
    size (a thing seen in pieces: an open drawer's front and, apart from it, its inside)."""
    import open3d as o3d

    if len(points) < 10:
        return np.arange(len(points))
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    labels = np.asarray(cloud.cluster_dbscan(eps=gap, min_points=3))
    if labels.max() < 0:
        return np.arange(len(points))
    sizes = np.bincount(labels[labels >= 0])
    if share >= 1.0:
        return np.flatnonzero(labels == sizes.argmax())
    return np.flatnonzero(np.isin(labels, np.flatnonzero(sizes >= share * sizes.max())))


def build_instances(
    matched: Sequence[MatchedObject],
    points: np.ndarray,
    normals: np.ndarray,
    memberships: Sequence[Sequence[np.ndarray]],
    projections: Sequence[Projection],
    support: float,
    box_areas: Sequence[Sequence[float]] | None = None,
    min_points: int = 30,
    pieces: Collection[str] = (),
) -> list[Instance3D]:
    """An :class:`Instance3D` per matched object with at least ``min_points`` points above ``support`` (the
    table's height). Objects are one connected piece; things labelled one of ``pieces`` (furniture parts) may
    show as several (:data:`PIECE_SHARE`).

    A point claimed by several objects goes to the one with the smallest boxes (``box_areas[v][i]``: pixels of
    box ``i`` in view ``v``): a small thing in front of a large one is seen inside the large one's boxes too.
    """
    above = points[:, 2] > support + SUPPORT_MARGIN
    masks = [instance_mask(obj, memberships, projections) & above for obj in matched]
    if box_areas is not None and len(masks) > 1:
        sizes = np.array([_mean_area(obj, box_areas) for obj in matched])
        claimed = np.stack(masks)
        owner = np.where(claimed, sizes[:, None], np.inf).argmin(axis=0)
        masks = [m & (owner == k) for k, m in enumerate(masks)]
    kept: list[tuple[MatchedObject, np.ndarray]] = []
    for obj, mask in zip(matched, masks, strict=True):
        idx = np.flatnonzero(mask)
        if len(idx) >= min_points:
            kept.append((obj, idx))
    kept = _merge_fragments(kept, points)
    out = []
    for obj, idx in kept:
        idx = idx[largest_cluster(points[idx], share=PIECE_SHARE if obj.label in pieces else 1.0)]
        if len(idx) < min_points:
            continue
        out.append(Instance3D(obj.label, points[idx], normals[idx], object_box(points[idx], support), obj.boxes))
    return out


def _merge_fragments(
    kept: list[tuple[MatchedObject, np.ndarray]], points: np.ndarray
) -> list[tuple[MatchedObject, np.ndarray]]:
    """Folds an object seen in fewer views into one of the same label whose box it overlaps: a view where the
    object was partly hidden (by the arm) gives a box that matches no other view's, and a second, partial
    copy of the object."""
    order = sorted(range(len(kept)), key=lambda k: -sum(b != -1 for b in kept[k][0].boxes))
    merged: list[tuple[MatchedObject, np.ndarray]] = []
    for k in order:
        obj, idx = kept[k]
        box = fit_box(points[idx])
        host = next(
            (
                m
                for m, (other, other_idx) in enumerate(merged)
                if other.label == obj.label and _box_overlap(box, fit_box(points[other_idx])) > 0.25
            ),
            None,
        )
        if host is None:
            merged.append((obj, idx))
        else:
            other, other_idx = merged[host]
            merged[host] = (other, np.union1d(other_idx, idx))
    return merged


def _box_overlap(a: Box3D, b: Box3D) -> float:
    """The share of the smaller box's volume inside the other."""
    smaller = min(a.volume, b.volume)
    return a.intersection(b).volume / smaller if smaller > 0 else 0.0


def _mean_area(obj: MatchedObject | Instance3D, box_areas: Sequence[Sequence[float]]) -> float:
    areas = [box_areas[v][i] for v, i in enumerate(obj.boxes) if i != -1]
    return float(np.mean(areas)) if areas else float("inf")


FLOOR_REACH = 0.02  # metres round an object's footprint within which what it stands on shows beside it
FLOOR_UPWARD = 0.8  # normal's z above which a point of what it stands on faces up
FLOOR_TOLERANCE = 0.002  # metres over an object's lowest seen point that a floor beside it may stand
FLOOR_POINTS = 10  # fewer such points than this: no floor is seen
FLOOR_LAYER = 0.004  # metres: the thickness of the layer of those points that is the floor
FLOOR_LAYER_POINTS = 5  # the fewest points such a layer holds (fewer are strays)
ON_TOP = 0.01  # metres below another's seen top within which an object's lowest seen point stands on that top
RESTING_GAP = 0.03  # metres over another's seen top within which an object's lowest seen point may rest on it
HIDDEN_FOOT = 0.06  # metres of an object's underside the cameras may not see (a ball's lower half, a bowl's stem)


def _may_rest_on(instance: Instance3D, other: Instance3D) -> bool:
    """Whether ``instance`` may stand on ``other``: their footprints overlap, and its lowest seen point is above
    ``other``'s bottom and at most :data:`RESTING_GAP` over its top (a box on a plate's floor stands below the
    plate's rim; a block on a box a little over the box's seen top)."""
    box, below = instance.box, other.box
    return bool(
        np.all(below.lower[:2] < box.upper[:2])
        and np.all(box.lower[:2] < below.upper[:2])
        and below.lower[2] < box.lower[2] < below.upper[2] + RESTING_GAP
    )


def _seen_bottom(instance: Instance3D) -> float:
    """The height of ``instance``'s lowest seen layer (:func:`lowest_layer`), not of its lowest point: a few points
    of a box's side below a block's 2D boxes, kept as the block's, stood 1.6 cm under the box's top, and the block
    was taken to stand on the table through the box."""
    low = lowest_layer(instance.points[:, 2])
    lowest = float(instance.box.lower[2])
    return lowest if low is None else max(low - FLOOR_LAYER / 2, lowest)


def _on_a_top(instance: Instance3D, others: Sequence[Instance3D]) -> bool:
    """Whether ``instance``'s seen bottom (:func:`_seen_bottom`) is near the seen top of one of ``others`` (a block
    on a box whose top it hides: no floor shows beside it)."""
    if not others:
        return False
    bottom = _seen_bottom(instance)
    return any(-ON_TOP < bottom - other.box.upper[2] < RESTING_GAP for other in others)


def floor_under(instance: Instance3D, supports: Sequence[Instance3D]) -> float | None:
    """The height of what ``instance`` stands on, as seen beside it: the lowest layer of a few of the upward-facing
    points of ``supports`` within :data:`FLOOR_REACH` of its footprint and below its lowest seen point (a plate's
    floor round a box lying on it, a bowl's bottom round the apple in it, a box's top round the block on it); None
    where too few show."""
    box = instance.box
    near = [
        s.points[
            (s.normals[:, 2] > FLOOR_UPWARD)
            & np.all(s.points[:, :2] > box.lower[:2] - FLOOR_REACH, axis=1)
            & np.all(s.points[:, :2] < box.upper[:2] + FLOOR_REACH, axis=1)
            & (s.points[:, 2] < box.lower[2] + FLOOR_TOLERANCE)
        ]
        for s in supports
    ]
    heights = np.concatenate([p[:, 2] for p in near]) if near else np.zeros(0)
    if len(heights) < FLOOR_POINTS:
        return None
    # The lowest layer that holds a few points, not the lowest points: of a box's top that a block on it hides, a
    # thin ring shows, and two points of the table at the box's foot put the block 4 cm under its top. Lowest, not
    # densest: a bowl's rim round the apple in it may show more than its bottom does.
    return lowest_layer(heights)


def lowest_layer(heights: np.ndarray) -> float | None:
    """The middle of the lowest :data:`FLOOR_LAYER` thick layer of ``heights`` that holds
    :data:`FLOOR_LAYER_POINTS` or more (fewer are strays); None where no layer does."""
    heights = np.sort(heights)
    in_layer = np.searchsorted(heights, heights + FLOOR_LAYER, side="right") - np.arange(len(heights))
    layers = np.flatnonzero(in_layer >= FLOOR_LAYER_POINTS)
    if not len(layers):
        return None
    start = int(layers[0])
    return float(np.median(heights[start : start + int(in_layer[start])]))


def ground(instances: Sequence[Instance3D], support: float) -> list[Instance3D]:
    """Each instance's box reaches down to what it stands on: the floor seen beside it of the things it may rest
    on (:func:`floor_under`); else, unless it stands on another's top that it hides, where its lowest seen point
    floats a little above the table, the table: what the cameras do not see of a ball's underside or a footed
    bowl's stem is still there, and what they do not see of an apple in a bowl reaches down to the bowl's bottom."""
    out = []
    for instance in instances:
        box = instance.box
        supports = [o for o in instances if o is not instance and _may_rest_on(instance, o)]
        floor = floor_under(instance, supports)
        bottom = float(box.lower[2])
        if floor is not None:
            bottom = min(bottom, floor)
        elif 0 < bottom - support < HIDDEN_FOOT and not _on_a_top(instance, supports):
            bottom = support
        if bottom < box.lower[2]:
            grounded = Box3D(np.array([*box.lower[:2], bottom]), box.upper.copy())
            instance = Instance3D(instance.label, instance.points, instance.normals, grounded, instance.boxes)
        out.append(instance)
    return out
