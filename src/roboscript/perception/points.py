"""Point clouds from RGB-D frames: back-projection, normals from the depth image, per-entity selection."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.robot_io import CameraFrame


def point_map(frame: CameraFrame, hidden: np.ndarray | None = None) -> np.ndarray:
    """World coordinates of every pixel, (H, W, 3); NaN where the depth is 0 (nothing seen) and where ``hidden``
    (H, W) marks a pixel (the robot's own: no surface of the scene)."""
    h, w = frame.depth.shape
    k = frame.intrinsics
    u, v = np.meshgrid(np.arange(w, dtype=float), np.arange(h, dtype=float))
    z = frame.depth.astype(float)
    camera = np.stack([(u - k[0, 2]) * z / k[0, 0], (v - k[1, 2]) * z / k[1, 1], z], axis=-1)
    world = camera @ frame.extrinsics.rotation.T + frame.extrinsics.position
    world[z <= 0] = np.nan
    if hidden is not None:
        world[hidden] = np.nan
    return world


def robot_masks(frames: Sequence[CameraFrame], robot_index: int | None) -> list[np.ndarray | None]:
    """Per frame, the pixels that show the robot (segmentation index ``robot_index``); None where that cannot be
    told (no index, or a frame without segmentation)."""
    return [None if robot_index is None or f.segmentation is None else f.segmentation == robot_index for f in frames]


def surface_points(
    frames: Sequence[CameraFrame], masks: Sequence[np.ndarray | None] | None = None, stride: int = 1
) -> np.ndarray:
    """The depth pixels of ``frames`` (every ``stride``-th) in world coordinates, (N, 3), less those ``masks``
    marks (the robot's own). Depth pixels lie on the surfaces themselves; a fused surface blurs into a skirt a few
    millimetres high around objects' feet, which a finger reaching down beside a low box would find in its way."""
    clouds = []
    for k, frame in enumerate(frames):
        world = point_map(frame, None if masks is None else masks[k])[::stride, ::stride]
        clouds.append(world[np.isfinite(world).all(axis=-1)])
    return np.concatenate(clouds) if clouds else np.zeros((0, 3))


def normal_map(points: np.ndarray, camera_position: np.ndarray) -> np.ndarray:
    """Unit normals from neighbouring pixels' points, turned towards the camera; NaN where undefined."""
    du = np.full_like(points, np.nan)
    dv = np.full_like(points, np.nan)
    du[:, 1:-1] = points[:, 2:] - points[:, :-2]
    dv[1:-1] = points[2:] - points[:-2]
    n = np.cross(du, dv)
    norm = np.linalg.norm(n, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        n = n / norm
    flip = np.einsum("hwk,hwk->hw", n, camera_position - points) < 0
    n[flip] *= -1
    return n


def entity_points(frames: list[CameraFrame], entity: int, stride: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Points and normals of the pixels segmented as ``entity`` in every frame.

    Pixels on the segment's outline are dropped: their neighbours lie on the background, so their normals are
    meaningless.
    """
    return entities_points(frames, [entity], stride)[entity]


def entities_points(
    frames: list[CameraFrame], entities: Sequence[int], stride: int = 1
) -> dict[int, tuple[np.ndarray, np.ndarray]]:
    """:func:`entity_points` of several entities, each frame's points and normals computed once."""
    found: dict[int, tuple[list[np.ndarray], list[np.ndarray]]] = {e: ([], []) for e in entities}
    for frame in frames:
        if frame.segmentation is None:
            raise ValueError(f"frame {frame.name!r} has no segmentation; ground-truth points need it")
        world = normals = None
        for entity in entities:
            inner = _inner_pixels(frame.segmentation == entity, stride)
            if not inner.any():
                continue
            if world is None:
                world = point_map(frame)
                normals = normal_map(world, frame.extrinsics.position)
            p, nn = world[inner], normals[inner]
            ok = np.isfinite(p).all(axis=1) & np.isfinite(nn).all(axis=1)
            found[entity][0].append(p[ok])
            found[entity][1].append(nn[ok])
    return {
        e: (np.concatenate(ps), np.concatenate(ns)) if ps else (np.zeros((0, 3)), np.zeros((0, 3)))
        for e, (ps, ns) in found.items()
    }


def _inner_pixels(mask: np.ndarray, stride: int) -> np.ndarray:
    """The pixels of ``mask`` whose four neighbours are in it too, every ``stride``-th."""
    inner = mask.copy()
    inner[1:] &= mask[:-1]
    inner[:-1] &= mask[1:]
    inner[:, 1:] &= mask[:, :-1]
    inner[:, :-1] &= mask[:, 1:]
    if stride > 1:
        keep = np.zeros_like(inner)
        keep[::stride, ::stride] = True
        inner &= keep
    return inner
