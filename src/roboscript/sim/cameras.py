"""RGB-D cameras: the rig specification, intrinsics and extrinsics, and offscreen rendering.

Extrinsics follow the OpenCV convention used by perception code (x right, y down, z forward); MuJoCo cameras look
along their -z with y up, and :func:`camera_pose_opencv` converts. Depth is metric (metres along the optical axis).
Segmentation maps each pixel to an entity index of the world (see :class:`roboscript.sim.world.SimWorld`), -1 where
nothing named is seen.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from roboscript.geometry import Transform, matrix_to_quat, quat_to_mujoco
from roboscript.phases import timed
from roboscript.robot_io import CameraFrame


@dataclass(frozen=True)
class CameraSpec:
    """A fixed camera looking from ``position`` at ``look_at``; ``fovy`` is the vertical field of view in degrees."""

    name: str
    position: tuple[float, float, float]
    look_at: tuple[float, float, float]
    fovy: float = 45.0
    width: int = 640
    height: int = 480

    def rotation(self) -> np.ndarray:
        """World rotation of the MuJoCo camera frame (columns: x right, y up, z backward)."""
        forward = np.subtract(self.look_at, self.position)
        forward = forward / np.linalg.norm(forward)
        up = np.array([0.0, 0.0, 1.0]) if abs(forward[2]) < 0.999 else np.array([1.0, 0.0, 0.0])
        right = np.cross(forward, up)
        right /= np.linalg.norm(right)
        true_up = np.cross(right, forward)
        return np.column_stack([right, true_up, -forward])

    def intrinsics(self) -> np.ndarray:
        """The 3x3 pinhole matrix K for this camera's resolution and vertical field of view."""
        return pinhole_intrinsics(self.fovy, self.width, self.height)


def pinhole_intrinsics(fovy_degrees: float, width: int, height: int) -> np.ndarray:
    """The 3x3 pinhole matrix K of a camera with square pixels and vertical field of view ``fovy_degrees``."""
    f = height / 2 / math.tan(math.radians(fovy_degrees) / 2)
    return np.array([[f, 0, width / 2], [0, f, height / 2], [0, 0, 1.0]])


def default_camera_rig() -> tuple[CameraSpec, ...]:
    """Three RGB-D cameras, left, right and top, covering the table and the cabinet, as in the original rig."""
    return (
        CameraSpec("camera_left", (0.55, 0.85, 1.55), (-0.15, 0.15, 0.9), 55.0),
        CameraSpec("camera_right", (0.55, -0.85, 1.55), (-0.15, -0.05, 0.9), 55.0),
        CameraSpec("camera_top", (0.05, 0.05, 2.25), (-0.12, 0.05, 0.82), 55.0),
    )


def add_camera(spec: mujoco.MjSpec, camera: CameraSpec) -> None:
    quat = quat_to_mujoco(matrix_to_quat(camera.rotation()))
    spec.worldbody.add_camera(name=camera.name, pos=list(camera.position), quat=list(quat), fovy=camera.fovy)


def camera_pose_opencv(model: mujoco.MjModel, data: mujoco.MjData, name: str) -> Transform:
    """World pose of camera ``name`` in the OpenCV convention (z forward, y down)."""
    cam = data.camera(name)
    rotation = cam.xmat.reshape(3, 3) @ np.diag([1.0, -1.0, -1.0])
    out = np.eye(4)
    out[:3, :3] = rotation
    out[:3, 3] = cam.xpos
    return Transform.from_matrix(out)


class Renderer:
    """Renders RGB, depth and segmentation from named cameras; create once per world and reuse (costly to make).

    ``geom_to_entity`` maps each geom id to an entity index (or -1); segmentation pixels carry those indices.
    """

    def __init__(self, model: mujoco.MjModel, geom_to_entity: np.ndarray, width: int = 640, height: int = 480):
        self._model = model
        self._geom_to_entity = np.asarray(geom_to_entity, dtype=np.int32)
        self.width, self.height = width, height
        self._renderer = mujoco.Renderer(model, height=height, width=width)
        self._option = mujoco.MjvOption()

    def close(self) -> None:
        self._renderer.close()

    def _update(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> None:
        self._renderer.update_scene(data, camera=camera, scene_option=self._option)
        # Shadows and reflections cost 6-10x the render time on a CPU rasteriser and help no perception code.
        self._renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SHADOW] = False
        self._renderer.scene.flags[mujoco.mjtRndFlag.mjRND_REFLECTION] = False

    @timed("render")
    def rgb(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> np.ndarray:
        self._update(data, camera)
        return self._renderer.render().copy()

    @timed("render")
    def depth(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> np.ndarray:
        self._renderer.enable_depth_rendering()
        try:
            self._update(data, camera)
            depth = self._renderer.render().astype(np.float32)
        finally:
            self._renderer.disable_depth_rendering()
        # Far-plane pixels (nothing hit) are reported as 0, as RGB-D sensors report missing depth.
        far = self._model.vis.map.zfar * self._model.stat.extent
        depth[depth >= far * 0.999] = 0.0
        return depth

    @timed("render")
    def segmentation(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> np.ndarray:
        self._renderer.enable_segmentation_rendering()
        try:
            self._update(data, camera)
            seg = self._renderer.render()
        finally:
            self._renderer.disable_segmentation_rendering()
        ids, types = seg[..., 0], seg[..., 1]
        out = np.full(ids.shape, -1, dtype=np.int32)
        is_geom = (types == int(mujoco.mjtObj.mjOBJ_GEOM)) & (ids >= 0)
        out[is_geom] = self._geom_to_entity[ids[is_geom]]
        return out

    def capture(
        self,
        data: mujoco.MjData,
        camera: str,
        spec: CameraSpec | None = None,
        segmentation: bool = True,
        color: bool = True,
    ) -> CameraFrame:
        """Depth, and optionally RGB and segmentation, from camera ``name`` with its calibration."""
        if spec is not None and (spec.width, spec.height) != (self.width, self.height):
            raise ValueError(
                f"camera {camera!r} is {spec.width}x{spec.height} but this renderer renders "
                f"{self.width}x{self.height}; create a Renderer of that size"
            )
        intrinsics = pinhole_intrinsics(float(self._model.cam(camera).fovy[0]), self.width, self.height)
        return CameraFrame(
            name=camera,
            rgb=self.rgb(data, camera) if color else None,
            depth=self.depth(data, camera),
            segmentation=self.segmentation(data, camera) if segmentation else None,
            intrinsics=intrinsics,
            extrinsics=camera_pose_opencv(self._model, data, camera),
        )
