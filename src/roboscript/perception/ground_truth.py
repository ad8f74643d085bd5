"""Ground-truth perception: the object store answered from the simulator (the default in simulation).

Boxes, poses, joints and receptacles come from the simulated world's state. Object points, which the adaptive
grasp detector works on, are taken the way a real rig would see them: from the cameras' depth images, selected by
the simulator's segmentation, so the detector meets the same partial, noisy views it will meet on a robot. Each
object's fullest view so far is kept in the object's own frame and follows its pose, as an object tracker's would:
an arm that has just pulled a drawer hides half a mug from one camera, and a grasp detector shown only the other
half finds no pair of walls to close on.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from roboscript.backends.base import Backend
from roboscript.geometry import Box3D, Transform, quat_from_yaw
from roboscript.perception.base import (
    DRAWER_FRONT_CLEARANCE,
    ArticulationJoint,
    ObjectPoints,
    Perception,
    Receptacle,
    UnknownObjectError,
)
from roboscript.perception.footprints import footprint_of, outline_of
from roboscript.perception.points import entities_points, entity_points, robot_masks, surface_points
from roboscript.phases import timed
from roboscript.robot_io import CameraFrame
from roboscript.sim.furniture import drawer_interior


class GroundTruthPerception(Perception):
    """Perception from the simulator's state; needs a backend with ground truth (a simulation)."""

    def __init__(self, backend: Backend, point_stride: int = 2):
        if backend.ground_truth is None:
            raise ValueError("ground-truth perception needs a simulated backend; this backend has no ground truth")
        self.backend = backend
        self.gt = backend.ground_truth
        self.world = self.gt.world
        self.point_stride = point_stride
        self._frames: list[CameraFrame] | None = None
        self._frames_state: tuple[float, bytes] | None = None  # the world's state the frames were rendered in
        self._views: dict[str, tuple[np.ndarray, np.ndarray]] = {}  # each object's fullest view, in its own frame

    @timed("perceive")
    def detect(self, categories: list[str] | None = None) -> None:
        """Looks with the cameras and keeps each object's view (the rest is read from the simulator's state)."""
        objects = [self.world.entity(n) for n in self.objects()]
        seen = entities_points(self._camera_frames(), [e.index for e in objects], self.point_stride)
        for entity in objects:
            self._keep_view(entity.name, *seen[entity.index])

    def names(self) -> list[str]:
        return self.gt.names()

    def objects(self) -> list[str]:
        return self.world.entity_names(("object",))

    def _entity(self, name: str):
        if name not in self.names():
            raise UnknownObjectError(name, self.names())
        return self.world.entity(name)

    def box(self, name: str) -> Box3D:
        self._entity(name)
        return self.gt.box(name)

    def pose(self, name: str) -> Transform:
        self._entity(name)
        return self.gt.pose(name)

    def footprint(self, name: str) -> tuple[np.ndarray, float, np.ndarray]:
        entity = self._entity(name)
        box = self.gt.box(name)
        pose = self.gt.pose(name)
        rotation = pose.rotation
        upright = rotation[2, 2] > math.cos(math.radians(35))
        if entity.object_type is None:
            return box.center[:2], 0.0, box.size[:2] / 2
        if not upright:  # lying on its side (a banana rolled over): the least rectangle round its parts
            return footprint_of(self.gt.outline(name), trim=0.0)
        yaw = math.atan2(rotation[1, 0], rotation[0, 0])
        frame = Transform(pose.position, quat_from_yaw(yaw))
        local = self.gt.local_box(name, frame)
        center = frame.apply(local.center[None])[0]
        return center[:2], yaw, local.size[:2] / 2

    def outline(self, name: str) -> np.ndarray:
        """Of objects, the convex outline of their geoms from above; of furniture, its box's."""
        if self._entity(name).object_type is None:
            return super().outline(name)
        return outline_of(self.gt.outline(name), trim=0.0)

    def joints(self, name: str) -> list[ArticulationJoint]:
        entity = self._entity(name)
        if entity.kind == "furniture":
            parts = [
                e.name
                for e in self.world.entities
                if e.kind == "part" and e.joint >= 0 and e.name.startswith(name + ".")
            ]
        elif entity.kind == "part":
            parts = [name]
        else:
            return []
        out = []
        for part in parts:
            info = self.gt.joint(part)
            owner = part if self.world.entity(part).joint >= 0 else _moving_part(self.world, part)
            out.append(
                ArticulationJoint(owner, info.type, info.position, info.axis, info.value, info.lower, info.upper)
            )
        return out

    def plane_normal(self, name: str, position: np.ndarray) -> np.ndarray:
        self._entity(name)
        model, data = self.world.model, self.world.data
        position = np.asarray(position, dtype=float)
        best, best_distance = None, math.inf
        for g in self.gt.geoms(name):
            if model.geom_type[g] != mujoco.mjtGeom.mjGEOM_BOX:
                continue
            rotation = data.geom_xmat[g].reshape(3, 3)
            half = model.geom_size[g]
            local = rotation.T @ (position - data.geom_xpos[g])
            for axis in range(3):
                for sign in (-1.0, 1.0):
                    # Distance from the point to this face (a rectangle).
                    on_face = np.clip(local, -half, half)
                    on_face[axis] = sign * half[axis]
                    distance = float(np.linalg.norm(local - on_face))
                    if distance < best_distance:
                        best_distance = distance
                        best = sign * rotation[:, axis]
        if best is None:  # no flat faces (a fruit): the normal of the box face nearest the point
            box = self.gt.box(name)
            gaps = np.concatenate([position - box.lower, box.upper - position])
            k = int(np.argmin(np.abs(gaps)))
            best = np.zeros(3)
            best[k % 3] = -1.0 if k < 3 else 1.0
        return np.asarray(best, dtype=float)

    def _camera_frames(self) -> list[CameraFrame]:
        """The cameras' frames of the world as it is now: rendered again only when something has moved since."""
        data = self.world.data
        state = (self.backend.time(), data.qpos.tobytes() + data.mocap_pos.tobytes() + data.mocap_quat.tobytes())
        if self._frames is None or state != self._frames_state:
            # Points need depth and segmentation only; rendering colour would cost more than both.
            self._frames = [self.backend.capture(c, color=False) for c in self.backend.camera_names()]
            self._frames_state = state
        return self._frames

    @timed("perceive")
    def points(self, name: str) -> ObjectPoints:
        """What the cameras see of ``name`` now; of an object, its fullest view so far where now shows less."""
        entity = self._entity(name)
        points, normals = entity_points(self._camera_frames(), entity.index, self.point_stride)
        if entity.kind != "object":
            return ObjectPoints(points, normals)
        return self._keep_view(name, points, normals)

    def _keep_view(self, name: str, points: np.ndarray, normals: np.ndarray) -> ObjectPoints:
        """Keeps this view of object ``name`` if it shows more than the one kept; returns the fuller of the two."""
        pose = self.gt.pose(name)
        kept = self._views.get(name)
        if kept is None or len(points) >= len(kept[0]):
            self._views[name] = (pose.inverse().apply(points), normals @ pose.rotation)
            return ObjectPoints(points, normals)
        local_points, local_normals = kept
        return ObjectPoints(pose.apply(local_points), local_normals @ pose.rotation.T)

    @timed("perceive")
    def scene_points(self) -> np.ndarray:
        frames = self._camera_frames()
        return surface_points(frames, robot_masks(frames, self.world.entity("robot").index), self.point_stride)

    def last_frames(self) -> list[CameraFrame]:
        return self._camera_frames()

    def last_masks(self) -> list:
        return robot_masks(self._camera_frames(), self.world.entity("robot").index)

    def receptacle(self, name: str) -> Receptacle | None:
        entity = self._entity(name)
        if entity.kind == "object":
            kind = entity.object_type
            if kind is None or not kind.container or kind.interior is None:
                return None
            lower, upper = (np.array(v, dtype=float) for v in kind.interior)
            return Receptacle(name, self.gt.pose(name), lower, upper, kind.round_floor)
        if entity.kind == "part" and entity.category == "drawer":
            body = entity.bodies[0]
            lower, upper = drawer_interior(self.world.model, name)
            frame = Transform.from_rotation(self.world.data.xpos[body], self.world.data.xmat[body].reshape(3, 3))
            opening = self.gt.joint(name).value
            # The part still inside the carcass cannot be reached from above.
            lower = lower.copy()
            lower[0] = max(lower[0], -opening + DRAWER_FRONT_CLEARANCE)
            return Receptacle(name, frame, lower, upper)
        if entity.kind == "part" and entity.category == "door":
            frame, lower, upper = self.gt.compartment(name)
            return Receptacle(name, frame, lower, upper)
        return None


def _moving_part(world, part: str) -> str:
    """The drawer or door a handle belongs to."""
    model = world.model
    body = world.entity(part).bodies[0]
    while model.body_jntnum[body] == 0 and body > 0:
        body = model.body_parentid[body]
    return model.body(body).name
