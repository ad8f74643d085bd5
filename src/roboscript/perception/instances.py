"""3D instances from matched 2D boxes: the fused points each object's boxes agree on, and a 3D box fitted to them.

A point belongs to an object when it lies in the object's box in at least one view and no view that saw the
object contradicts it (sees the point, outside the object's box there): with several views this carves the
object's visual hull out of the fused surface. What remains of the table around the object's foot is cut off at
the table's height.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.matching import MatchedObject, Projection

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


def support_height(points: np.ndarray, bin_size: float = 0.002) -> float:
    """Height of the scene's dominant horizontal surface (the table): the densest thin layer of points."""
    z = points[:, 2]
    counts, edges = np.histogram(z, bins=np.arange(z.min(), z.max() + 2 * bin_size, bin_size))
    peak = int(np.argmax(counts))
    return float(edges[peak + 1])


def fit_box(points: np.ndarray, trim: float = 1.0) -> Box3D:
    """The axis-aligned box of ``points``, ``trim`` percent cut from each side per axis against stray points."""
    if len(points) == 0:
        raise ValueError("cannot fit a box to no points")
    lower = np.percentile(points, trim, axis=0)
    upper = np.percentile(points, 100 - trim, axis=0)
    return Box3D(lower, upper)


def build_instances(
    matched: Sequence[MatchedObject],
    points: np.ndarray,
    normals: np.ndarray,
    memberships: Sequence[Sequence[np.ndarray]],
    projections: Sequence[Projection],
    support: float,
    min_points: int = 30,
) -> list[Instance3D]:
    """An :class:`Instance3D` per matched object with at least ``min_points`` points above ``support`` (the
    table's height)."""
    out = []
    above = points[:, 2] > support + SUPPORT_MARGIN
    for obj in matched:
        idx = np.flatnonzero(instance_mask(obj, memberships, projections) & above)
        if len(idx) < min_points:
            continue
        out.append(Instance3D(obj.label, points[idx], normals[idx], fit_box(points[idx]), obj.boxes))
    return out
