"""Which pieces of a frame's segmentation touch, and what their shared border looks like: the evidence on which
:mod:`roboscript.perception.detection.segment_merging` decides whether two pieces are one thing.

A border is every pair of neighbouring pixels, one in each piece. Along it: how many pairs lie on one surface in 3D,
how many meet in a concave crease (things touching), how far the colours step. Of each piece: its size, colour,
height and extent.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from roboscript.perception.detection.segments import GAP_PIXELS, NEAR, Segmentation

PAIR_FEATURES = 28


@dataclass
class PieceStats:
    """Per piece: pixel count, mean colour (0-1), colour spread, lowest, middle and highest point above the table,
    horizontal extent (metres, the 90% spread along its two main directions) and centre."""

    pixels: np.ndarray  # (n,)
    colour: np.ndarray  # (n, 3)
    spread: np.ndarray  # (n,)
    heights: np.ndarray  # (n, 3)
    extent: np.ndarray  # (n, 2)
    centre: np.ndarray  # (n, 3)


@dataclass
class Borders:
    """Adjacent piece pairs ``(a, b)`` with ``a < b``, and per pair its border's evidence."""

    pairs: np.ndarray  # (m, 2)
    length: np.ndarray  # (m,) neighbouring pixel pairs on the border
    near: np.ndarray  # (m,) share of them close in 3D
    crease: np.ndarray  # (m,) share meeting in a concave crease
    colour_step: np.ndarray  # (m,) median largest channel step across the border (0-1)


def piece_stats(seg: Segmentation) -> PieceStats:
    """:class:`PieceStats` of every piece of ``seg``."""
    fp, labels, n = seg.frame, seg.labels, seg.count
    flat = labels.ravel()
    keep = flat >= 0
    ids = flat[keep]
    points = fp.points.reshape(-1, 3)[keep]
    colours = fp.colours.reshape(-1, 3)[keep] / 255.0
    pixels = np.bincount(ids, minlength=n).astype(float)
    colour = np.stack([np.bincount(ids, colours[:, c], n) for c in range(3)], axis=1) / np.maximum(pixels, 1)[:, None]
    spread = np.sqrt(np.bincount(ids, np.sum((colours - colour[ids]) ** 2, axis=1), n) / np.maximum(pixels, 1))
    table = seg.table_height if np.isfinite(seg.table_height) else float(np.nanmin(points[:, 2], initial=0.0))
    heights = np.zeros((n, 3))
    extent = np.zeros((n, 2))
    centre = np.zeros((n, 3))
    order = np.argsort(ids, kind="stable")
    bounds = np.concatenate([[0], np.cumsum(np.bincount(ids, minlength=n))])
    for k in range(n):
        p = points[order[bounds[k] : bounds[k + 1]]]
        z = p[:, 2] - table
        heights[k] = np.percentile(z, [2, 50, 98])
        centre[k] = p.mean(axis=0)
        extent[k] = horizontal_extent(p[:, :2])
    return PieceStats(pixels, colour, spread, heights, extent, centre)


def horizontal_extent(xy: np.ndarray) -> np.ndarray:
    """The 90% spread of ``xy`` along its main direction and across it, metres (largest first)."""
    if len(xy) < 3:
        return np.zeros(2)
    centred = xy - xy.mean(axis=0)
    _, _, axes = np.linalg.svd(centred, full_matrices=False)
    along = centred @ axes.T
    low, high = np.percentile(along, [5, 95], axis=0)
    return np.sort(high - low)[::-1]


def borders(seg: Segmentation) -> Borders:
    """The borders between pieces of ``seg`` that touch in the image."""
    fp, labels = seg.frame, seg.labels
    keys, near, crease, step = [], [], [], []
    for a, b in (((slice(None), slice(0, -1)), (slice(None), slice(1, None))),
                 ((slice(0, -1), slice(None)), (slice(1, None), slice(None)))):  # fmt: skip
        la, lb = labels[a], labels[b]
        edge = (la >= 0) & (lb >= 0) & (la != lb)
        lo, hi = np.minimum(la[edge], lb[edge]), np.maximum(la[edge], lb[edge])
        pa, pb = fp.points[a][edge], fp.points[b][edge]
        gap = np.linalg.norm(pa - pb, axis=-1)
        size = np.maximum(fp.pixel_size[a][edge], fp.pixel_size[b][edge])
        na, nb = fp.normals[a][edge], fp.normals[b][edge]
        bent = np.einsum("ik,ik->i", na, nb) < 0.5
        concave = np.einsum("ik,ik->i", na - nb, pb - pa) > 0
        keys.append(lo.astype(np.int64) * seg.count + hi)
        near.append(gap < NEAR + GAP_PIXELS * size)
        crease.append(np.nan_to_num(bent & concave).astype(bool))
        step.append(np.max(np.abs(fp.colours[a][edge] - fp.colours[b][edge]), axis=-1) / 255.0)
    key = np.concatenate(keys)
    if key.size == 0:
        empty = np.zeros(0)
        return Borders(np.zeros((0, 2), dtype=int), empty, empty, empty, empty)
    unique, inverse, length = np.unique(key, return_inverse=True, return_counts=True)
    near_share = np.bincount(inverse, np.concatenate(near)) / length
    crease_share = np.bincount(inverse, np.concatenate(crease)) / length
    steps = np.concatenate(step)
    colour_step = _grouped_median(steps, inverse, length)
    pairs = np.stack([unique // seg.count, unique % seg.count], axis=1)
    return Borders(pairs, length.astype(float), near_share, crease_share, colour_step)


def _grouped_median(values: np.ndarray, group: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """The (lower) median of ``values`` within each group (``group``: 0..g-1; ``counts``: each group's size)."""
    order = np.lexsort((values, group))
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    return values[order][starts + (counts - 1) // 2]


def pair_features(stats: PieceStats, edges: Borders) -> np.ndarray:
    """One row of :data:`PAIR_FEATURES` numbers per border: the border's evidence and both pieces' stats, the
    larger piece first (the order of a pair says nothing)."""
    a, b = edges.pairs[:, 0], edges.pairs[:, 1]
    swap = stats.pixels[b] > stats.pixels[a]
    big, small = np.where(swap, b, a), np.where(swap, a, b)

    def piece(k: np.ndarray) -> list[np.ndarray]:
        return [
            np.log1p(stats.pixels[k]),
            *stats.colour[k].T,
            stats.spread[k],
            *stats.heights[k].T,
            *stats.extent[k].T,
        ]

    dz = stats.centre[small, 2] - stats.centre[big, 2]
    dxy = np.linalg.norm(stats.centre[small, :2] - stats.centre[big, :2], axis=1)
    colour_gap = np.abs(stats.colour[big] - stats.colour[small]).max(axis=1)
    rows = [
        np.log1p(edges.length),
        edges.length / np.sqrt(np.maximum(stats.pixels[small], 1)),
        edges.near,
        edges.crease,
        edges.colour_step,
        colour_gap,
        dz,
        dxy,
        *piece(big),
        *piece(small),
    ]
    out = np.stack(rows, axis=1)
    assert out.shape[1] == PAIR_FEATURES
    return out
