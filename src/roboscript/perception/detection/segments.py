"""Class-agnostic segmentation of one RGB-D frame into the surfaces that stand on the table.

Works on every ``stride``-th pixel. The table is the dominant level plane the depth image shows; what rises above it
(less the robot's own pixels, which its model tells) is cut into pieces where neighbouring pixels are far apart in
3D, differ in colour, or meet in a concave crease (a mug standing on a plate meets it in one; a box's own edges are
convex and keep it whole). Pieces are deliberately small: a cap and its bottle, a box's two colours, come apart
here and are joined again by :mod:`roboscript.perception.detection.segment_merging`, which learned when to.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from roboscript.robot_io import CameraFrame

STRIDE = 2  # the segmentation works on every second pixel of each row and column
ABOVE_TABLE = 0.005  # metres above the table's plane from which a point belongs to something standing on it
LEVEL = 0.9  # a surface is level where its normal's z is at least this
NEAR = 0.004  # metres: neighbours closer than this, plus GAP_PIXELS pixel sizes, lie on one surface
GAP_PIXELS = 2.5
COLOUR_STEP = 28.0  # largest difference of any channel (0-255) between neighbours of one piece
CREASE = 0.5  # cosine: neighbours whose normals differ more than this and meet concavely are cut apart
MIN_PIXELS = 12  # pieces with fewer (working) pixels join a neighbour on their surface, or are dropped


@dataclass
class FramePoints:
    """A frame at the working resolution: world points, unit normals facing the camera, colours (0-255, float),
    the pixel size in metres at each pixel, and which pixels are valid (depth seen, not the robot)."""

    points: np.ndarray  # (h, w, 3)
    normals: np.ndarray  # (h, w, 3)
    colours: np.ndarray  # (h, w, 3)
    pixel_size: np.ndarray  # (h, w)
    valid: np.ndarray  # (h, w) bool
    stride: int


@dataclass
class Piece:
    """One connected piece: its working pixels as flat indices into the working image."""

    pixels: np.ndarray


@dataclass
class Segmentation:
    """The pieces of one frame and the table under them: ``labels`` gives each working pixel its piece, -1 for
    none; ``table_height`` is the plane's height (NaN where no table was seen)."""

    frame: FramePoints
    labels: np.ndarray  # (h, w) int
    count: int
    table_height: float


def frame_points(frame: CameraFrame, hidden: np.ndarray | None = None, stride: int = STRIDE) -> FramePoints:
    """``frame`` at every ``stride``-th pixel; ``hidden`` (full resolution) marks pixels that are not the scene's
    (the robot's own)."""
    if frame.rgb is None:
        raise ValueError(f"frame {frame.name!r} has no colour image; the detector needs RGB-D frames")
    depth = frame.depth[::stride, ::stride].astype(float)
    h, w = depth.shape
    rows, cols = np.indices((h, w)) * stride
    k = frame.intrinsics
    camera = np.stack([(cols - k[0, 2]) * depth / k[0, 0], (rows - k[1, 2]) * depth / k[1, 1], depth], axis=-1)
    points = camera @ frame.extrinsics.rotation.T + frame.extrinsics.position
    valid = depth > 0
    if hidden is not None:
        valid &= ~hidden[::stride, ::stride]
    points[~valid] = np.nan
    du = np.full_like(points, np.nan)
    dv = np.full_like(points, np.nan)
    du[:, 1:-1] = points[:, 2:] - points[:, :-2]
    dv[1:-1] = points[2:] - points[:-2]
    normals = np.cross(du, dv)
    with np.errstate(invalid="ignore", divide="ignore"):
        normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
        facing = np.einsum("hwk,hwk->hw", normals, frame.extrinsics.position - points)
    normals[facing < 0] *= -1
    colours = frame.rgb[::stride, ::stride].astype(float)
    pixel_size = depth * stride / k[0, 0]
    return FramePoints(points, normals, colours, pixel_size, valid, stride)


def table_height(fp: FramePoints) -> float:
    """Height of the largest level plane the frame shows (the table's top); NaN if it shows none."""
    level = fp.valid & (fp.normals[..., 2] > LEVEL)
    z = fp.points[..., 2][level]
    z = z[np.isfinite(z)]
    if z.size < 50:
        return float("nan")
    bins = np.arange(z.min(), z.max() + 0.01, 0.005)
    if len(bins) < 2:
        return float(np.median(z))
    counts, edges = np.histogram(z, bins)
    peak = edges[int(np.argmax(counts))] + 0.0025
    near = z[np.abs(z - peak) < 0.005]
    return float(np.median(near))


def segment(fp: FramePoints, table: float | None = None) -> Segmentation:
    """Cuts what stands above the table into pieces (see the module's description)."""
    table = table_height(fp) if table is None else table
    z = fp.points[..., 2]
    with np.errstate(invalid="ignore"):
        above = fp.valid & (z > table + ABOVE_TABLE) if np.isfinite(table) else fp.valid.copy()
    h, w = above.shape
    index = np.arange(h * w).reshape(h, w)
    sources, targets = [], []
    for a, b in (((slice(None), slice(0, -1)), (slice(None), slice(1, None))),
                 ((slice(0, -1), slice(None)), (slice(1, None), slice(None)))):  # fmt: skip
        joined = above[a] & above[b] & _joined(fp, a, b)
        sources.append(index[a][joined])
        targets.append(index[b][joined])
    src, dst = np.concatenate(sources), np.concatenate(targets)
    graph = coo_matrix((np.ones(src.size, dtype=np.int8), (src, dst)), shape=(h * w, h * w))
    _, component = connected_components(graph, directed=False)
    component = component.reshape(h, w)
    component[~above] = -1
    component = _absorb_crumbs(fp, component, above)
    labels = np.full((h, w), -1)
    ids, counts = np.unique(component[above], return_counts=True)
    kept = ids[counts >= MIN_PIXELS]
    remap = np.full(h * w, -1)
    remap[kept] = np.arange(kept.size)
    labels[above] = remap[component[above]]
    return Segmentation(fp, labels, int(kept.size), table)


def _absorb_crumbs(fp: FramePoints, component: np.ndarray, above: np.ndarray) -> np.ndarray:
    """Pieces too small to stand alone (a mug's thin rim between its inside and the arm in front of it, a
    highlight) join the piece they share most border with, where the two lie on one surface in 3D there; with no
    such neighbour they are dropped."""
    ids, counts = np.unique(component[above], return_counts=True)
    small = np.zeros(component.max() + 2, dtype=bool)
    small[ids[counts < MIN_PIXELS]] = True
    if not small.any():
        return component
    keys = []
    for a, b in (((slice(None), slice(0, -1)), (slice(None), slice(1, None))),
                 ((slice(0, -1), slice(None)), (slice(1, None), slice(None)))):  # fmt: skip
        ca, cb = component[a], component[b]
        gap = np.linalg.norm(fp.points[a] - fp.points[b], axis=-1)
        with np.errstate(invalid="ignore"):
            near = gap < NEAR + GAP_PIXELS * np.maximum(fp.pixel_size[a], fp.pixel_size[b])
        edge = (ca >= 0) & (cb >= 0) & (ca != cb) & near
        for crumb, other in ((ca[edge], cb[edge]), (cb[edge], ca[edge])):
            mine = small[crumb] & ~small[other]
            keys.append(np.stack([crumb[mine], other[mine]], axis=1))
    pairs = np.concatenate(keys)
    if len(pairs) == 0:
        return component
    unique, length = np.unique(pairs, axis=0, return_counts=True)
    order = np.lexsort((-length, unique[:, 0]))  # per crumb, its longest border first
    unique = unique[order]
    first = np.concatenate([[True], unique[1:, 0] != unique[:-1, 0]])
    target = np.arange(component.max() + 2)
    target[unique[first, 0]] = unique[first, 1]
    out = component.copy()
    out[above] = target[component[above]]
    return out


def _joined(fp: FramePoints, a: tuple, b: tuple) -> np.ndarray:
    """Whether the neighbouring pixels ``a`` and ``b`` (slices of the image) lie on one piece."""
    pa, pb = fp.points[a], fp.points[b]
    gap = np.linalg.norm(pa - pb, axis=-1)
    near = gap < NEAR + GAP_PIXELS * np.maximum(fp.pixel_size[a], fp.pixel_size[b])
    colour = np.max(np.abs(fp.colours[a] - fp.colours[b]), axis=-1) < COLOUR_STEP
    na, nb = fp.normals[a], fp.normals[b]
    bent = np.einsum("hwk,hwk->hw", na, nb) < CREASE
    # Concave where the normals turn towards each other across the step from a to b.
    concave = np.einsum("hwk,hwk->hw", na - nb, pb - pa) > 0
    crease = bent & concave
    with np.errstate(invalid="ignore"):
        return near & colour & ~np.nan_to_num(crease, nan=0).astype(bool)
