"""Cross-view matching: which 2D boxes in different views show the same object.

The fused points are projected into every view. A box is described by the binary vector of the points that fall
inside it and are visible there (their depth agrees with the view's depth image, so points hidden behind the
object do not count). Boxes of different views are scored by the IoU of those vectors and matched greedily, best
pair first: each box joins at most one object, an object holds at most one box per view, and views where it was
not found hold -1. The object's label is the majority of its boxes' labels.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.perception.detection.grounding import Detection2D
from roboscript.robot_io import CameraFrame

VISIBILITY_TOLERANCE = 0.01  # metres a point may lie behind the depth image's surface and still count as seen


@dataclass(frozen=True)
class Projection:
    """The fused points as one view sees them: pixel coordinates, and whether each point is visible there."""

    u: np.ndarray  # (N,) int column, -1 off the image
    v: np.ndarray  # (N,) int row
    visible: np.ndarray  # (N,) bool
    z: np.ndarray  # (N,) distance along the camera's axis, metres


def project(points: np.ndarray, frame: CameraFrame, tolerance: float = VISIBILITY_TOLERANCE) -> Projection:
    """Pixels of ``points`` in ``frame``; a point is visible where it is in the image and not behind the surface
    the depth image shows."""
    to_camera = frame.extrinsics.inverse()
    camera = points @ to_camera.rotation.T + to_camera.position
    z = camera[:, 2]
    k = frame.intrinsics
    h, w = frame.depth.shape
    with np.errstate(divide="ignore", invalid="ignore"):
        u = np.floor(k[0, 0] * camera[:, 0] / z + k[0, 2]).astype(np.int64, copy=False)
        v = np.floor(k[1, 1] * camera[:, 1] / z + k[1, 2]).astype(np.int64, copy=False)
    inside = (z > 0) & (u >= 0) & (u < w) & (v >= 0) & (v < h)
    u = np.where(inside, u, -1)
    v = np.where(inside, v, -1)
    seen = np.zeros(len(points), dtype=bool)
    depth = frame.depth[v[inside], u[inside]]
    seen[inside] = (depth > 0) & (z[inside] <= depth + tolerance)
    return Projection(u, v, seen, z)


def pixel_depths(
    points: np.ndarray, frame: CameraFrame, mask: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per point: the view's depth at its pixel, the point's own depth from the camera, and whether the pixel says
    anything (in the image, a finite positive depth, not among ``mask``'s pixels: the robot's, which say nothing of
    what is behind them)."""
    seen = project(points, frame)
    inside = seen.u >= 0
    depth = np.zeros(len(points))
    depth[inside] = frame.depth[seen.v[inside], seen.u[inside]]
    informative = inside & np.isfinite(depth) & (depth > 0)
    if mask is not None:
        informative[inside] &= ~mask[seen.v[inside], seen.u[inside]]
    return depth, seen.z, informative


def membership(projection: Projection, box: tuple[int, int, int, int]) -> np.ndarray:
    """The box's binary vector: visible points whose pixel lies in the box."""
    x0, y0, x1, y1 = box
    p = projection
    return p.visible & (p.u >= x0) & (p.u < x1) & (p.v >= y0) & (p.v < y1)


def vector_iou(a: np.ndarray, b: np.ndarray) -> float:
    union = np.count_nonzero(a | b)
    return np.count_nonzero(a & b) / union if union else 0.0


@dataclass(frozen=True)
class MatchedObject:
    """One object across views: ``boxes[v]`` is the index of its box in view ``v``'s detections, or -1."""

    label: str
    boxes: tuple[int, ...]
    votes: dict[str, int]


def match_views(
    memberships: Sequence[Sequence[np.ndarray]],
    detections: Sequence[Sequence[Detection2D]],
    min_iou: float = 0.1,
) -> list[MatchedObject]:
    """Greedy matching of boxes across views by the IoU of their point-membership vectors.

    ``memberships[v][i]`` and ``detections[v][i]`` describe box ``i`` of view ``v``. Boxes that match nothing
    become objects of their own (seen in one view).
    """
    views = len(memberships)
    if len(detections) != views or any(len(m) != len(d) for m, d in zip(memberships, detections, strict=True)):
        raise ValueError("memberships and detections must have one entry per view and per box")
    pairs = []
    for a in range(views):
        for b in range(a + 1, views):
            for i, mi in enumerate(memberships[a]):
                for j, mj in enumerate(memberships[b]):
                    iou = vector_iou(mi, mj)
                    if iou >= min_iou:
                        pairs.append((iou, a, i, b, j))
    pairs.sort(key=lambda p: -p[0])
    group_of: dict[tuple[int, int], int] = {}
    groups: list[list[int]] = []
    for _, a, i, b, j in pairs:
        ga, gb = group_of.get((a, i)), group_of.get((b, j))
        if ga is None and gb is None:
            group = [-1] * views
            group[a], group[b] = i, j
            groups.append(group)
            group_of[(a, i)] = group_of[(b, j)] = len(groups) - 1
        elif ga is not None and gb is None and groups[ga][b] == -1:
            groups[ga][b] = j
            group_of[(b, j)] = ga
        elif gb is not None and ga is None and groups[gb][a] == -1:
            groups[gb][a] = i
            group_of[(a, i)] = gb
        elif ga is not None and gb is not None and ga != gb:
            first, second = groups[ga], groups[gb]
            if all(x == -1 or y == -1 for x, y in zip(first, second, strict=True)):  # no view holds two boxes
                for view, box in enumerate(second):
                    if box != -1:
                        first[view] = box
                        group_of[(view, box)] = ga
                groups[gb] = [-1] * views
    for view in range(views):
        for i in range(len(detections[view])):
            if (view, i) not in group_of:
                group = [-1] * views
                group[view] = i
                groups.append(group)
    out = []
    for group in groups:
        if all(i == -1 for i in group):
            continue
        votes = Counter(detections[v][i].label for v, i in enumerate(group) if i != -1)
        label = max(sorted(votes), key=lambda name: votes[name])  # ties: alphabetical, so results are stable
        out.append(MatchedObject(label, tuple(group), dict(votes)))
    return out
