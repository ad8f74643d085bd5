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

from roboscript.errors import InvalidArgumentError
from roboscript.geometry import Transform, matrix_to_quat, quat_to_mujoco
from roboscript.phases import timed
from roboscript.robot_io import CameraFrame
from roboscript.sim.shared_gl import gl_renderer


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
    Without ``antialiasing`` the colour images have jagged edges, depth and segmentation are the same (they are
    rendered without multisampling either way), and the renderer is made in about half the time and renders a
    third faster on a CPU rasteriser: the choice for depth and segmentation alone.
    """

    def __init__(
        self,
        model: mujoco.MjModel,
        geom_to_entity: np.ndarray,
        width: int = 640,
        height: int = 480,
        antialiasing: bool = True,
    ):
        self._model = model
        self._geom_to_entity = np.asarray(geom_to_entity, dtype=np.int32)
        self.width, self.height = width, height
        self.antialiasing = antialiasing
        # Where the process shares renderers, the GL side may be one made for another build of the same world.
        self._renderer, self._shared = gl_renderer(
            model, width, height, antialiasing, lambda: _make_gl(model, width, height, antialiasing)
        )
        self._option = mujoco.MjvOption()

    def close(self) -> None:
        if not self._shared:
            self._renderer.close()

    def _update(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> None:
        self._renderer._model = self._model  # mujoco.Renderer builds the scene from it (a shared one: anyone's)
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
        """Metres along each pixel's optical axis; 0 where nothing was hit, as RGB-D sensors report it."""
        _, buffer, scene = self._id_pass(data, camera, colour=False)
        return self._metric_depth(buffer, scene)

    @timed("render")
    def segmentation(self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera) -> np.ndarray:
        """The entity index seen at each pixel, -1 where none."""
        colour, _, scene = self._id_pass(data, camera, colour=True)
        return self._entities(colour, scene)

    @timed("render")
    def depth_and_segmentation(
        self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera
    ) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`depth` and :meth:`segmentation` from one render pass, at the cost of either."""
        colour, buffer, scene = self._id_pass(data, camera, colour=True)
        return self._metric_depth(buffer, scene), self._entities(colour, scene)

    def _id_pass(
        self, data: mujoco.MjData, camera: str | int | mujoco.MjvCamera, colour: bool
    ) -> tuple[np.ndarray | None, np.ndarray, mujoco.MjvScene]:
        """One render in MuJoCo's segmentation mode (each geom in a colour of its own, depth as rendered): the
        ID colours if asked, the raw depth buffer, and the scene that maps colours back to geoms."""
        self._update(data, camera)
        renderer = self._renderer
        scene = renderer.scene
        flags = scene.flags.copy()
        scene.flags[mujoco.mjtRndFlag.mjRND_SEGMENT] = True
        scene.flags[mujoco.mjtRndFlag.mjRND_IDCOLOR] = True
        ids = np.empty((self.height, self.width, 3), dtype=np.uint8) if colour else None
        depth = np.empty((self.height, self.width), dtype=np.float32)
        # mujoco.Renderer reads one buffer a pass; both are read here, with its context and viewport as it uses
        # them (mujoco is pinned; tests/test_backend_interface.py compares with its own passes).
        try:
            if renderer._gl_context:
                renderer._gl_context.make_current()
            mujoco.mjr_render(renderer._rect, scene, renderer._mjr_context)
            mujoco.mjr_readPixels(ids, depth, renderer._rect, renderer._mjr_context)
        finally:
            np.copyto(scene.flags, flags)
        if renderer._gl_context:  # offscreen GL reads bottom row first
            ids = None if ids is None else np.flipud(ids)
            depth = np.flipud(depth)
        return ids, depth, scene

    def _metric_depth(self, buffer: np.ndarray, scene: mujoco.MjvScene) -> np.ndarray:
        """Metres along the optical axis from the depth buffer (reversed Z, as MuJoCo renders), 0 where far."""
        extent = self._model.stat.extent
        near, far = np.float32(self._model.vis.map.znear * extent), np.float32(self._model.vis.map.zfar * extent)
        z = buffer.astype(np.float64)
        if scene.camera[0].orthographic:
            metric = far - z * (far - near)
        else:
            c = -(far + near) / (far - near)
            d = -(np.float32(2) * far * near) / (far - near)
            metric = (np.float32(-0.5) * d) / (z + (np.float32(-0.5) * c - np.float32(0.5)))
        depth = metric.astype(np.float32)
        # Far-plane pixels (nothing hit) are reported as 0, as RGB-D sensors report missing depth.
        depth[depth >= self._model.vis.map.zfar * extent * 0.999] = 0.0
        return depth

    def _entities(self, colour: np.ndarray, scene: mujoco.MjvScene) -> np.ndarray:
        """Entity indices from an ID-coloured image: colour -> scene geom -> model geom -> entity, -1 elsewhere."""
        segment = colour[..., 0].astype(np.int64) | (colour[..., 1].astype(np.int64) << 8)
        segment |= colour[..., 2].astype(np.int64) << 16
        # Segment 0 is the background; a colour past the last segment (none is expected) is read as background.
        lookup = np.full(scene.ngeom + 2, -1, dtype=np.int32)
        for g in scene.geoms[: scene.ngeom]:
            if g.segid != -1 and g.objtype == int(mujoco.mjtObj.mjOBJ_GEOM) and g.objid >= 0:
                lookup[g.segid + 1] = self._geom_to_entity[g.objid]
        return lookup[np.minimum(segment, scene.ngeom + 1)]

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
            raise InvalidArgumentError(
                f"camera {camera!r} is {spec.width}x{spec.height} but this renderer renders "
                f"{self.width}x{self.height}; create a Renderer of that size"
            )
        intrinsics = pinhole_intrinsics(float(self._model.cam(camera).fovy[0]), self.width, self.height)
        if segmentation:
            depth, entities = self.depth_and_segmentation(data, camera)
        else:
            depth, entities = self.depth(data, camera), None
        return CameraFrame(
            name=camera,
            rgb=self.rgb(data, camera) if color else None,
            depth=depth,
            segmentation=entities,
            intrinsics=intrinsics,
            extrinsics=camera_pose_opencv(self._model, data, camera),
        )


def _make_gl(model: mujoco.MjModel, width: int, height: int, antialiasing: bool) -> mujoco.Renderer:
    if antialiasing:
        return mujoco.Renderer(model, height=height, width=width)
    # The offscreen buffer is sized and sampled from the model when the context is made, and only then.
    quality, buffer = model.vis.quality, model.vis.global_
    saved = (quality.offsamples, buffer.offwidth, buffer.offheight)
    quality.offsamples, buffer.offwidth, buffer.offheight = 0, width, height
    try:
        return mujoco.Renderer(model, height=height, width=width)
    finally:
        quality.offsamples, buffer.offwidth, buffer.offheight = saved
