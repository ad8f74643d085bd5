"""Which pixels of a camera frame show the robot itself, told from its model and its joint readings alone.

A real rig has no segmentation image that labels the arm: it knows the arm's model and where its joints are, and
that is enough. The robot's visual model, posed at the joint states read with the frame, is ray-cast from the
camera through the pixels it may cover (the image rectangles of its geoms' boxes); a pixel is the robot's where a
ray hits the model and the depth image shows a surface no nearer than that hit (less a tolerance for the model's
small differences from the real arm): something nearer stands in front of the arm and is the scene's.

Rays are cast every ``stride`` pixels and the mask is grown by two working pixels, so the arm's outline is covered
rather than fringed: grown by one, some 10-35 pixels of a 640x480 view still showed the arm, and each became a
surface point in mid-air that the planning scene remembered.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import mujoco
import numpy as np

from roboscript.geometry import Transform
from roboscript.perception.detection.pixel_masks import grown
from roboscript.perception.points import image_span
from roboscript.robot_io import CameraFrame
from roboscript.robots import RobotDescription
from roboscript.robots.mujoco_model import compiled_robot

VISUAL_GROUP = 2  # the geom group of the robots' visual meshes (the Menagerie convention); collision meshes are 3
TOLERANCE = 0.02  # metres the depth image may lie in front of the model's surface and still show the robot
STRIDE = 2  # rays are cast every second pixel of each row and column
MAX_RANGE = 10.0  # metres: rays go no farther


class SelfFilter:
    """Robot masks for frames of the robot ``description`` mounted at ``mount``; ``joint_states`` reads its
    joints (names as in its model, unprefixed: :meth:`Backend.joint_states`)."""

    def __init__(
        self,
        description: RobotDescription,
        mount: Transform,
        tolerance: float = TOLERANCE,
        stride: int = STRIDE,
    ):
        self.description, self.tolerance, self.stride = description, tolerance, stride
        self.model = compiled_robot(description, mount)
        self.data = mujoco.MjData(self.model)
        self._visual = np.flatnonzero(self.model.geom_group == VISUAL_GROUP)
        if self._visual.size == 0:
            raise ValueError(f"the {description.name} model has no visual geoms (group {VISUAL_GROUP}) to filter with")
        self._groups = np.zeros(mujoco.mjNGROUP, dtype=np.uint8)
        self._groups[VISUAL_GROUP] = 1
        self._qpos = {}
        for j in range(self.model.njnt):
            name = self.model.joint(j).name.removeprefix(RobotDescription.qualified(""))
            self._qpos[name] = int(self.model.jnt_qposadr[j])

    def pose(self, joint_states: Mapping[str, float]) -> None:
        """Poses the model at ``joint_states``; joints the readings leave out keep their last value."""
        for name, value in joint_states.items():
            adr = self._qpos.get(name)
            if adr is not None:
                self.data.qpos[adr] = value
        mujoco.mj_kinematics(self.model, self.data)

    def masks(
        self,
        frames: Sequence[CameraFrame],
        joint_states: Mapping[str, float],
        wanted: Sequence[np.ndarray] | None = None,
    ) -> list[np.ndarray]:
        """Per frame, the (H, W) pixels that show the robot posed at ``joint_states``; with ``wanted`` (per frame,
        the (H, W) pixels whose answer matters), only those are told (and the pixels within the mask's growth of
        them), the rest left unmarked."""
        self.pose(joint_states)
        return [self._mask(f, None if wanted is None else wanted[k]) for k, f in enumerate(frames)]

    def _mask(self, frame: CameraFrame, wanted: np.ndarray | None = None) -> np.ndarray:
        h, w = frame.depth.shape
        s = self.stride
        candidates = self._candidates(frame, (h + s - 1) // s, (w + s - 1) // s)
        if wanted is not None:
            candidates &= grown(grown(_any_in_blocks(wanted, s)))
        rows, cols = np.nonzero(candidates)
        out = np.zeros(((h + s - 1) // s, (w + s - 1) // s), dtype=bool)
        if rows.size:
            k = frame.intrinsics
            u, v = cols * s, rows * s
            rays = np.stack([(u - k[0, 2]) / k[0, 0], (v - k[1, 2]) / k[1, 1], np.ones(u.size)], axis=1)
            along = np.linalg.norm(rays, axis=1)  # the ray's length per metre of depth
            directions = (rays / along[:, None]) @ frame.extrinsics.rotation.T
            geom = np.full(u.size, -1, dtype=np.int32)
            distance = np.zeros(u.size)
            mujoco.mj_multiRay(
                self.model, self.data, np.asarray(frame.extrinsics.position, dtype=float),
                np.ascontiguousarray(directions).ravel(), self._groups, 1, -1, geom, distance, None, u.size,
                MAX_RANGE,
            )  # fmt: skip
            hit = geom >= 0
            seen = frame.depth[v, u].astype(float)
            model_depth = distance / along
            robot = hit & ((seen <= 0) | ~np.isfinite(seen) | (seen > model_depth - self.tolerance))
            out[rows[robot], cols[robot]] = True
        out = grown(grown(out))
        return np.repeat(np.repeat(out, s, axis=0), s, axis=1)[:h, :w]

    def _candidates(self, frame: CameraFrame, h: int, w: int) -> np.ndarray:
        """The working pixels inside the image rectangle of some visual geom's box (its bounding sphere where the
        box is behind the camera in part)."""
        out = np.zeros((h, w), dtype=bool)
        signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
        for g in self._visual:
            center, half = self.model.geom_aabb[g, :3], self.model.geom_aabb[g, 3:]
            rotation = self.data.geom_xmat[g].reshape(3, 3)
            corners = self.data.geom_xpos[g] + (center + signs * half) @ rotation.T
            span = image_span(frame, corners, self.stride)
            if span is None:
                continue
            r0, r1, c0, c1 = span
            if c1 > c0 and r1 > r0:
                out[r0:r1, c0:c1] = True
        return out


def _any_in_blocks(mask: np.ndarray, s: int) -> np.ndarray:
    """Per working pixel (an ``s`` x ``s`` block of ``mask``), whether any pixel of its block is set."""
    h, w = mask.shape
    padded = np.zeros(((h + s - 1) // s * s, (w + s - 1) // s * s), dtype=bool)
    padded[:h, :w] = mask
    return padded.reshape(padded.shape[0] // s, s, padded.shape[1] // s, s).any(axis=(1, 3))
