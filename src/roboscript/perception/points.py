"""Point clouds from RGB-D frames: back-projection, normals from the depth image, per-entity selection."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from roboscript.geometry import Box3D
from roboscript.phases import timed
from roboscript.robot_io import CameraFrame


@timed("perceive")
def point_map(
    frame: CameraFrame, hidden: np.ndarray | None = None, window: tuple[slice, slice] | None = None
) -> np.ndarray:
    """World coordinates of every pixel, (H, W, 3), or of the pixels of ``window`` (rows, columns); NaN where the
    depth is 0 (nothing seen) and where ``hidden`` (H, W) marks a pixel (the robot's own: no surface of the
    scene)."""
    h, w = frame.depth.shape
    rows_in, cols_in = window or (slice(0, h), slice(0, w))
    rows, cols = np.mgrid[rows_in, cols_in]
    world = _pixels_to_world(frame, rows.ravel(), cols.ravel()).reshape(*rows.shape, 3)
    if hidden is not None:
        world[hidden[rows_in, cols_in]] = np.nan
    return world


def pixels_outside(frame: CameraFrame, box: Box3D) -> np.ndarray:
    """The (H, W) pixels whose point lies outside ``box`` or that see nothing: a look confined to where one thing
    can be. Points are made only inside the image rectangle the box's corners span."""
    h, w = frame.depth.shape
    out = np.ones((h, w), dtype=bool)
    r0, r1, c0, c1 = image_span(frame, box.corners()) or (0, h, 0, w)
    if r1 <= r0 or c1 <= c0:
        return out
    rows, cols = np.indices((r1 - r0, c1 - c0)).reshape(2, -1)
    world = _pixels_to_world(frame, rows + r0, cols + c0)
    inside = np.all((world > box.lower) & (world < box.upper), axis=1)  # NaN (no depth) is outside
    out[r0:r1, c0:c1] = ~inside.reshape(r1 - r0, c1 - c0)
    return out


def image_span(frame: CameraFrame, corners: np.ndarray, stride: int = 1) -> tuple[int, int, int, int] | None:
    """The image rectangle (first row, row past the last, first column, column past the last; in blocks of
    ``stride`` pixels, clipped to the image) that the world points ``corners`` span in ``frame``: the whole image
    where some lie behind the camera's plane, None where all do."""
    h, w = frame.depth.shape
    rows, cols = (h + stride - 1) // stride, (w + stride - 1) // stride
    to_camera = frame.extrinsics.inverse()
    camera = np.asarray(corners, dtype=float) @ to_camera.rotation.T + to_camera.position
    behind = camera[:, 2] <= 0.01
    if behind.all():
        return None
    if behind.any():  # straddles the camera's plane: any pixel may see it
        return 0, rows, 0, cols
    k = frame.intrinsics
    u = k[0, 0] * camera[:, 0] / camera[:, 2] + k[0, 2]
    v = k[1, 1] * camera[:, 1] / camera[:, 2] + k[1, 2]
    c0, c1 = max(int(np.floor(u.min() / stride)), 0), min(int(np.ceil(u.max() / stride)) + 1, cols)
    r0, r1 = max(int(np.floor(v.min() / stride)), 0), min(int(np.ceil(v.max() / stride)) + 1, rows)
    return r0, r1, c0, c1


def evenly_spread(points: np.ndarray, most: int) -> np.ndarray:
    """At most ``most`` of ``points``, evenly spread through the array (all of them where there are no more)."""
    if len(points) <= most:
        return points
    return points[np.linspace(0, len(points) - 1, most).astype(int)]


def robot_masks(frames: Sequence[CameraFrame], robot_index: int | None) -> list[np.ndarray | None]:
    """Per frame, the pixels that show the robot (segmentation index ``robot_index``); None where that cannot be
    told (no index, or a frame without segmentation)."""
    return [None if robot_index is None or f.segmentation is None else f.segmentation == robot_index for f in frames]


def without_pixels(frame: CameraFrame, mask: np.ndarray | None) -> CameraFrame:
    """``frame`` with no depth where ``mask`` is set (the robot's own pixels: a detector looks at the rest)."""
    if mask is None:
        return frame
    return replace(frame, depth=np.where(mask, 0, frame.depth).astype(frame.depth.dtype, copy=False))


@timed("perceive")
def surface_points(
    frames: Sequence[CameraFrame], masks: Sequence[np.ndarray | None] | None = None, stride: int = 1
) -> np.ndarray:
    """The depth pixels of ``frames`` (every ``stride``-th) in world coordinates, (N, 3), less those ``masks``
    marks (the robot's own). Depth pixels lie on the surfaces themselves; a fused surface blurs into a skirt a few
    millimetres high around objects' feet, which a finger reaching down beside a low box would find in its way."""
    clouds = []
    for k, frame in enumerate(frames):
        # Only the pixels kept are back-projected: a full frame costs some 100 ms, a quarter of it a quarter.
        keep = frame.depth[::stride, ::stride] > 0
        hidden = None if masks is None else masks[k]
        if hidden is not None:
            keep &= ~hidden[::stride, ::stride]
        rows, cols = np.nonzero(keep)
        clouds.append(_pixels_to_world(frame, rows * stride, cols * stride))
    return np.concatenate(clouds) if clouds else np.zeros((0, 3))


@timed("perceive")
def normal_map(points: np.ndarray, camera_position: np.ndarray) -> np.ndarray:
    """Unit normals from neighbouring pixels' points, turned towards the camera; NaN where undefined."""
    du = np.full_like(points, np.nan)
    dv = np.full_like(points, np.nan)
    du[:, 1:-1] = points[:, 2:] - points[:, :-2]
    dv[1:-1] = points[2:] - points[:-2]
    return _unit_normals_facing(du, dv, points, camera_position)


def _unit_normals_facing(du: np.ndarray, dv: np.ndarray, points: np.ndarray, camera: np.ndarray) -> np.ndarray:
    """Unit normals ``du x dv`` at ``points`` (any leading shape, last axis xyz), each turned towards ``camera``."""
    n = np.cross(du, dv)
    with np.errstate(invalid="ignore", divide="ignore"):
        n = n / np.linalg.norm(n, axis=-1, keepdims=True)
    n[np.einsum("...k,...k->...", n, camera - points) < 0] *= -1
    return n


@timed("perceive")
def entity_points(frames: list[CameraFrame], entity: int, stride: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Points and normals of the pixels segmented as ``entity`` in every frame.

    Pixels on the segment's outline are dropped: their neighbours lie on the background, so their normals are
    meaningless.
    """
    return entities_points(frames, [entity], stride)[entity]


@timed("perceive")
def entities_points(
    frames: list[CameraFrame], entities: Sequence[int], stride: int = 1
) -> dict[int, tuple[np.ndarray, np.ndarray]]:
    """:func:`entity_points` of several entities.

    Points and normals are computed at the chosen pixels only, the normals from the same neighbours as
    :func:`normal_map`'s: an object covers a few thousand of a frame's 300,000 pixels."""
    found: dict[int, tuple[list[np.ndarray], list[np.ndarray]]] = {e: ([], []) for e in entities}
    for frame in frames:
        if frame.segmentation is None:
            raise ValueError(f"frame {frame.name!r} has no segmentation; ground-truth points need it")
        rows, cols = np.nonzero(_inner_pixels_of_any(frame.segmentation, stride))
        labels = frame.segmentation[rows, cols]
        for entity in entities:
            mine = labels == entity
            if not mine.any():
                continue
            p, nn = _points_and_normals(frame, rows[mine], cols[mine])
            ok = np.isfinite(p).all(axis=1) & np.isfinite(nn).all(axis=1)
            found[entity][0].append(p[ok])
            found[entity][1].append(nn[ok])
    return {
        e: (np.concatenate(ps), np.concatenate(ns)) if ps else (np.zeros((0, 3)), np.zeros((0, 3)))
        for e, (ps, ns) in found.items()
    }


class DepthSurface:
    """Points and normals of one frame's pixels in image rectangles, made only where asked: what :func:`point_map`
    and :func:`normal_map` give there (``hidden`` pixels, the robot's own, have no point, and their neighbours no
    normal). The refinement of a look reads every other pixel of each 2D box; whole-frame maps for it were a
    tenth of a second a frame."""

    def __init__(self, frame: CameraFrame, hidden: np.ndarray | None = None):
        self.frame, self.hidden = frame, hidden

    def within(self, box: tuple[int, int, int, int], stride: int = 1) -> tuple[np.ndarray, np.ndarray]:
        """Points and normals (N, 3) at every ``stride``-th pixel of ``box`` (x0, y0, x1, y1), row by row."""
        x0, y0, x1, y1 = box
        rows, cols = np.mgrid[y0:y1:stride, x0:x1:stride].reshape(2, -1)
        points, normals = _points_and_normals(self.frame, rows, cols)
        if self.hidden is not None:
            h, w = self.hidden.shape
            left, right = np.maximum(cols - 1, 0), np.minimum(cols + 1, w - 1)
            up, down = np.maximum(rows - 1, 0), np.minimum(rows + 1, h - 1)
            points[self.hidden[rows, cols]] = np.nan
            hidden = self.hidden
            normals[hidden[rows, left] | hidden[rows, right] | hidden[up, cols] | hidden[down, cols]] = np.nan
        return points, normals


class MapSurface:
    """:class:`DepthSurface`'s answers from point and normal maps (H, W, 3) already made."""

    def __init__(self, points: np.ndarray, normals: np.ndarray):
        self.points, self.normals = points, normals

    def within(self, box: tuple[int, int, int, int], stride: int = 1) -> tuple[np.ndarray, np.ndarray]:
        x0, y0, x1, y1 = box
        return (
            self.points[y0:y1:stride, x0:x1:stride].reshape(-1, 3),
            self.normals[y0:y1:stride, x0:x1:stride].reshape(-1, 3),
        )


def _pixels_to_world(frame: CameraFrame, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """World coordinates of the pixels ``(rows, cols)`` (index arrays of one shape); NaN where there is no
    depth."""
    k = frame.intrinsics
    z = frame.depth[rows, cols].astype(float)
    u, v = cols.astype(float), rows.astype(float)
    camera = np.stack([(u - k[0, 2]) * z / k[0, 0], (v - k[1, 2]) * z / k[1, 1], z], axis=-1)
    world = camera @ frame.extrinsics.rotation.T + frame.extrinsics.position
    world[z <= 0] = np.nan
    return world


def _points_and_normals(frame: CameraFrame, rows: np.ndarray, cols: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Points and :func:`normal_map`'s normals at the pixels ``(rows, cols)`` (NaN normals on the image's edge)."""
    h, w = frame.depth.shape
    points = _pixels_to_world(frame, rows, cols)
    left, right = np.maximum(cols - 1, 0), np.minimum(cols + 1, w - 1)
    up, down = np.maximum(rows - 1, 0), np.minimum(rows + 1, h - 1)
    du = _pixels_to_world(frame, rows, right) - _pixels_to_world(frame, rows, left)
    dv = _pixels_to_world(frame, down, cols) - _pixels_to_world(frame, up, cols)
    du[(cols == 0) | (cols == w - 1)] = np.nan
    dv[(rows == 0) | (rows == h - 1)] = np.nan
    return points, _unit_normals_facing(du, dv, points, frame.extrinsics.position)


def _inner_pixels_of_any(segmentation: np.ndarray, stride: int) -> np.ndarray:
    """The pixels whose four neighbours carry the same label as they do, every ``stride``-th: for each label, the
    pixels inside its segment rather than on its outline."""
    inner = np.ones(segmentation.shape, dtype=bool)
    inner[1:] &= segmentation[1:] == segmentation[:-1]
    inner[:-1] &= segmentation[:-1] == segmentation[1:]
    inner[:, 1:] &= segmentation[:, 1:] == segmentation[:, :-1]
    inner[:, :-1] &= segmentation[:, :-1] == segmentation[:, 1:]
    if stride > 1:
        keep = np.zeros_like(inner)
        keep[::stride, ::stride] = True
        inner &= keep
    return inner
