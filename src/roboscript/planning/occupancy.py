"""Occupancy from observed points: the points in a voxel grid, the occupied voxels merged into few boxes, each box
shrunk to the points it holds.

A planning scene built from what the cameras saw (rather than from the simulator's geometry) is made of such
boxes. Plain voxels would stand up to a voxel proud of the surfaces they stand for: the table would rise by
centimetres and a gripper reaching for a flat object would collide with it. Shrinking each box to its points keeps
surfaces where they were seen; a minimum thickness keeps a seen sheet a solid obstacle.
"""

from __future__ import annotations

import hashlib
import itertools
from dataclasses import dataclass

import numpy as np

VOXEL = 0.03  # metres: the grid that groups points into boxes
THICKNESS = 0.004  # metres: the least extent of a box along any axis
SIGNATURE_STEP = 0.005  # metres: thin voxels whose surfaces agree to this merge into one box


@dataclass(frozen=True)
class OccupiedBox:
    """An axis-aligned box of occupied space, world frame."""

    lower: np.ndarray
    upper: np.ndarray

    @property
    def center(self) -> np.ndarray:
        return (self.lower + self.upper) / 2

    @property
    def half_size(self) -> np.ndarray:
        return (self.upper - self.lower) / 2


def occupied_voxels(points: np.ndarray, voxel: float = VOXEL) -> set[tuple[int, int, int]]:
    """Integer indices of the voxels of size ``voxel`` that hold at least one point."""
    if voxel <= 0:
        raise ValueError(f"voxel must be a positive size in metres, got {voxel}")
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    if len(points) == 0:
        return set()
    cells, _ = unique_cells(np.floor(points / voxel).astype(np.int64))
    return {(int(i), int(j), int(k)) for i, j, k in cells}


def merge_voxels(cells: set[tuple[int, int, int]]) -> list[tuple[np.ndarray, np.ndarray]]:
    """Disjoint boxes of whole voxels that together are exactly ``cells``, as ``(first, last)`` inclusive voxel
    indices: runs along x, then equal runs stacked along y, then equal rectangles along z (greedy, not minimal,
    but a flat sheet becomes one box)."""
    by_layer: dict[int, dict[int, list[int]]] = {}
    for i, j, k in cells:
        by_layer.setdefault(k, {}).setdefault(j, []).append(i)
    layer_rects: dict[int, list[tuple[int, int, int, int]]] = {}
    for k, rows in by_layer.items():
        runs_by_row = {j: _runs(sorted(xs)) for j, xs in rows.items()}
        open_rects: dict[tuple[int, int], int] = {}  # (x0, x1) -> first row
        done: list[tuple[int, int, int, int]] = []
        for j in range(min(rows), max(rows) + 2):
            runs = set(runs_by_row.get(j, []))
            for run in list(open_rects):
                if run not in runs:
                    done.append((run[0], run[1], open_rects.pop(run), j - 1))
            for run in runs:
                open_rects.setdefault(run, j)
        layer_rects[k] = done
    boxes: list[tuple[np.ndarray, np.ndarray]] = []
    open_boxes: dict[tuple[int, int, int, int], int] = {}  # rectangle -> first layer
    layers = sorted(layer_rects)
    previous = None
    for k in [*layers, None]:
        present = set(layer_rects.get(k, [])) if k is not None else set()
        contiguous = previous is not None and k is not None and k == previous + 1
        for rect in list(open_boxes):
            if not contiguous or rect not in present:
                x0, x1, y0, y1 = rect
                boxes.append((np.array([x0, y0, open_boxes.pop(rect)]), np.array([x1, y1, previous])))
        for rect in present:
            open_boxes.setdefault(rect, k)
        previous = k
    return boxes


def _runs(xs: list[int]) -> list[tuple[int, int]]:
    """Maximal runs of consecutive integers in sorted ``xs``, as ``(first, last)``."""
    runs, start = [], xs[0]
    for a, b in itertools.pairwise(xs):
        if b != a + 1:
            runs.append((start, a))
            start = b
    runs.append((start, xs[-1]))
    return runs


def unique_cells(indices: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(indices, axis=0, return_inverse=True)`` for (N, D) integer cells, the same rows in the same
    (lexicographic) order: each row is packed into one integer, row-major over the cells' bounding range, so the
    sort is of N numbers rather than of N rows (a fifth of the time of building a perceived scene went to it)."""
    indices = np.asarray(indices, dtype=np.int64)
    if len(indices) == 0 or float(np.prod((np.ptp(indices, axis=0) + 1).astype(float))) >= 2**62:
        cells, inverse = np.unique(indices, axis=0, return_inverse=True)  # too wide to pack: the rows themselves
        return cells, inverse.reshape(-1)
    low = indices.min(axis=0)
    span = indices.max(axis=0) - low + 1
    keys = np.zeros(len(indices), dtype=np.int64)
    for column in range(indices.shape[1]):
        keys = keys * span[column] + (indices[:, column] - low[column])
    unique_keys, inverse = np.unique(keys, return_inverse=True)
    cells = np.empty((len(unique_keys), indices.shape[1]), dtype=np.int64)
    for column in reversed(range(indices.shape[1])):
        cells[:, column] = unique_keys % span[column] + low[column]
        unique_keys = unique_keys // span[column]
    return cells, inverse.reshape(-1)


def occupied_boxes(points: np.ndarray, voxel: float = VOXEL, thickness: float = THICKNESS) -> list[OccupiedBox]:
    """Boxes covering ``points``: each occupied voxel shrunk to the bounding box of its points, voxels whose
    shrunk boxes agree merged (:func:`merge_voxels`), every box grown to at least ``thickness`` along each axis
    (downwards only along z)."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    if thickness < 0:
        raise ValueError(f"thickness must be >= 0 metres, got {thickness}")
    if voxel <= 0:
        raise ValueError(f"voxel must be a positive size in metres, got {voxel}")
    if len(points) == 0:
        return []
    cells, inverse = unique_cells(np.floor(points / voxel).astype(np.int64))
    lows = np.full((len(cells), 3), np.inf)
    highs = np.full((len(cells), 3), -np.inf)
    np.minimum.at(lows, inverse, points)
    np.maximum.at(highs, inverse, points)
    # Voxels merge only with voxels whose points fill them alike: a table's cells with a box standing on it
    # would otherwise make one box as high as the box. Alike: thin along the same axes (a sheet seen edge-on),
    # at the same place along those axes; how much of a thick axis the points span does not matter.
    extent = highs - lows
    thin = extent < voxel / 2
    place = np.where(thin, np.round((lows + highs) / 2 / SIGNATURE_STEP), 0).astype(np.int64)
    # Cells grouped by signature, the groups in the order their first cells come.
    _, signature = unique_cells(np.column_stack([thin, place]).astype(np.int64))
    order = np.argsort(signature, kind="stable")
    runs = np.split(order, np.flatnonzero(np.diff(signature[order])) + 1)
    runs.sort(key=lambda members: int(members[0]))
    groups = [dict(zip(map(tuple, cells[members].tolist()), members.tolist(), strict=True)) for members in runs]
    members: list[int] = []  # the cells of every box, box after box
    starts: list[int] = []  # where each box's cells begin in members
    for index in groups:
        for first, last in merge_voxels(set(index)):
            starts.append(len(members))
            members.extend(
                index[(i, j, k)]
                for i in range(first[0], last[0] + 1)
                for j in range(first[1], last[1] + 1)
                for k in range(first[2], last[2] + 1)
            )
    cells_of = np.asarray(members, dtype=np.int64)
    lower = np.minimum.reduceat(lows[cells_of], starts, axis=0)
    upper = np.maximum.reduceat(highs[cells_of], starts, axis=0)
    grow = np.maximum(thickness - (upper - lower), 0.0)
    # A thin level sheet was seen from above (the cameras look down): it is solid below its surface, and a gripper
    # reaching for something flat on it must find its top where it was seen.
    down = np.zeros_like(grow)
    down[:, 2] = grow[:, 2]
    lower, upper = lower - grow / 2 - down / 2, upper + grow / 2 - down / 2
    return [OccupiedBox(lo, hi) for lo, hi in zip(lower, upper, strict=True)]


class RememberedBoxes:
    """:func:`occupied_boxes` that remembers its answers for the point sets of the last scene built: most of what a
    perceived scene is rebuilt from after a look or a release (the objects not moved, the furniture not touched)
    is what the scene before was built from, to the point."""

    def __init__(self) -> None:
        self._kept: dict[tuple, list[OccupiedBox]] = {}
        self._used: dict[tuple, list[OccupiedBox]] = {}
        self.hits = 0

    def boxes(self, points: np.ndarray, voxel: float = VOXEL) -> list[OccupiedBox]:
        """The boxes of ``points`` (as :func:`occupied_boxes`)."""
        points = np.ascontiguousarray(points, dtype=float).reshape(-1, 3)
        key = (voxel, points.shape, hashlib.blake2b(points.tobytes(), digest_size=16).digest())
        boxes = self._used.get(key)
        if boxes is None:
            boxes = self._kept.get(key)
        if boxes is None:
            boxes = occupied_boxes(points, voxel)
        else:
            self.hits += 1
        self._used[key] = boxes
        return boxes

    def next_scene(self) -> None:
        """What the scene just built used is kept for the next; the rest is forgotten."""
        self._kept, self._used = self._used, {}
