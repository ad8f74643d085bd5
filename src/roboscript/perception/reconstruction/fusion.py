"""TSDF fusion of calibrated RGB-D frames with Open3D (the ``perception`` extra): one surface from every view.

Depth images are checked before they are fused: a broken one (wrong shape, NaN, negative, nothing in range) is
reported and skipped, so one bad camera cannot spoil the surface the others see.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from roboscript.robot_io import CameraFrame


@dataclass(frozen=True)
class FusionSettings:
    """``voxel``: TSDF voxel edge (m); ``truncation``: signed-distance truncation (m); ``max_depth``: depth beyond
    this is ignored (m); ``min_valid``: the fraction of pixels with a depth in range below which a frame is
    rejected as broken; ``lowest``: the world height (m) below which surfaces are not fused, or None.

    ``lowest`` leaves out the floor under the table the arm stands on, which it cannot reach: seen past the table's
    edges it was a third of the fused points of the paper's worlds, and every later step of a look (projecting,
    matching, cutting out instances) went through them."""

    voxel: float = 0.005
    truncation: float = 0.02
    max_depth: float = 2.5
    min_valid: float = 0.05
    lowest: float | None = None

    def __post_init__(self) -> None:
        if self.voxel <= 0 or self.truncation <= self.voxel:
            raise ValueError(f"need 0 < voxel < truncation, got voxel={self.voxel}, truncation={self.truncation}")


@dataclass
class FusedScene:
    """What fusion produced: the surface as points (with normals), the frames used and the frames skipped with the
    reason."""

    points: np.ndarray  # (N, 3) world
    normals: np.ndarray  # (N, 3) unit
    used: list[str] = field(default_factory=list)
    skipped: dict[str, str] = field(default_factory=dict)
    seconds: float = 0.0  # wall time the fusion took
    _volume: object = None

    def mesh(self):
        """The fused surface as an Open3D triangle mesh (marching cubes; slower than the points)."""
        if self._volume is None:
            raise ValueError("no frame was fused, so there is no surface")
        mesh = self._volume.extract_triangle_mesh()
        mesh.compute_vertex_normals()
        return mesh


def depth_problem(frame: CameraFrame, settings: FusionSettings) -> str | None:
    """Why ``frame``'s depth cannot be fused, or None if it can."""
    depth = frame.depth
    if depth is None or depth.ndim != 2:
        return f"depth must be a 2D image, got {None if depth is None else depth.shape}"
    if depth.shape != frame.rgb.shape[:2]:
        h, w = frame.rgb.shape[:2]
        return f"depth is {depth.shape[1]}x{depth.shape[0]} but the colour image {w}x{h}"
    if not np.isfinite(depth).all():
        return f"{int((~np.isfinite(depth)).sum())} depth pixels are NaN or infinite"
    if (depth < 0).any():
        return f"{int((depth < 0).sum())} depth pixels are negative"
    valid = float(((depth > 0) & (depth < settings.max_depth)).mean())
    if valid < settings.min_valid:
        return f"only {valid:.1%} of depth pixels are in range (0, {settings.max_depth} m)"
    return None


def heights(frame: CameraFrame) -> np.ndarray:
    """The world height (m) of each depth pixel's point, (H, W); the camera's own height where there is no depth."""
    k, pose = frame.intrinsics, frame.extrinsics
    h, w = frame.depth.shape
    rotation = pose.rotation
    # A pixel's point is its depth times the ray (x, y, 1) through it, turned into the world: its height is the
    # depth times the ray's upward part, plus the camera's height.
    across = rotation[2, 0] * (np.arange(w) - k[0, 2]) / k[0, 0]
    down = rotation[2, 1] * (np.arange(h) - k[1, 2]) / k[1, 1]
    rise = down[:, None] + across[None, :] + rotation[2, 2]
    return frame.depth * rise + pose.position[2]


def fuse(
    frames: Sequence[CameraFrame], settings: FusionSettings | None = None, masks: Sequence[np.ndarray] | None = None
) -> FusedScene:
    """Integrates every usable frame into one TSDF volume and extracts its surface points.

    ``masks``: per frame, pixels to leave out (True = drop), e.g. the robot's own body.
    """
    import open3d as o3d

    started = time.perf_counter()
    settings = settings or FusionSettings()
    # No colour is fused: nothing reads the surface's colours (detection reads the images), and fusing them was a
    # quarter of the fusion's time.
    volume = o3d.pipelines.integration.ScalableTSDFVolume(
        voxel_length=settings.voxel,
        sdf_trunc=settings.truncation,
        color_type=o3d.pipelines.integration.TSDFVolumeColorType.NoColor,
    )
    used, skipped = [], {}
    for i, frame in enumerate(frames):
        problem = depth_problem(frame, settings)
        if problem is not None:
            skipped[frame.name] = problem
            continue
        depth = np.array(frame.depth, dtype=np.float32)
        if masks is not None and masks[i] is not None:
            depth[masks[i]] = 0.0
        if settings.lowest is not None:
            depth[heights(frame) < settings.lowest] = 0.0
        h, w = depth.shape
        k = frame.intrinsics
        intrinsic = o3d.camera.PinholeCameraIntrinsic(w, h, k[0, 0], k[1, 1], k[0, 2], k[1, 2])
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(
            o3d.geometry.Image(np.ascontiguousarray(frame.rgb, dtype=np.uint8)),
            o3d.geometry.Image(depth),
            depth_scale=1.0,
            depth_trunc=settings.max_depth,
            convert_rgb_to_intensity=False,
        )
        volume.integrate(rgbd, intrinsic, frame.extrinsics.inverse().matrix())
        used.append(frame.name)
    if not used:
        return FusedScene(np.zeros((0, 3)), np.zeros((0, 3)), used, skipped, 0.0)
    cloud = volume.extract_point_cloud()
    points = np.asarray(cloud.points)
    normals = np.asarray(cloud.normals) if cloud.has_normals() else np.zeros_like(points)
    return FusedScene(points, normals, used, skipped, time.perf_counter() - started, volume)
