"""Rigid transforms and axis-aligned boxes shared by every layer.

Quaternions in this project's public types are (x, y, z, w), as in ROS. MuJoCo stores (w, x, y, z); the
conversion happens only at the simulator boundary, through :func:`quat_from_mujoco` and :func:`quat_to_mujoco`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

Vector3 = np.ndarray


def quat_from_mujoco(wxyz: np.ndarray) -> np.ndarray:
    """(w, x, y, z) -> (x, y, z, w)."""
    w, x, y, z = np.asarray(wxyz, dtype=float)
    return np.array([x, y, z, w])


def quat_to_mujoco(xyzw: np.ndarray) -> np.ndarray:
    """(x, y, z, w) -> (w, x, y, z)."""
    x, y, z, w = np.asarray(xyzw, dtype=float)
    return np.array([w, x, y, z])


def quat_to_matrix(xyzw: np.ndarray) -> np.ndarray:
    """Rotation matrix of a unit quaternion given as (x, y, z, w)."""
    x, y, z, w = np.asarray(xyzw, dtype=float) / np.linalg.norm(xyzw)
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def matrix_to_quat(rotation: np.ndarray) -> np.ndarray:
    """(x, y, z, w) of a rotation matrix, with w >= 0."""
    m = np.asarray(rotation, dtype=float)
    trace = np.trace(m)
    if trace > 0:
        s = 2.0 * np.sqrt(trace + 1.0)
        q = np.array([(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s])
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = np.array([0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s])
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = np.array([(m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s])
    else:
        s = 2.0 * np.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = np.array([(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s])
    q /= np.linalg.norm(q)
    return q if q[3] >= 0 else -q


def quat_from_yaw(yaw: float) -> np.ndarray:
    """(x, y, z, w) of a rotation by ``yaw`` radians about world z."""
    return np.array([0.0, 0.0, np.sin(yaw / 2), np.cos(yaw / 2)])


def quat_from_axis_angle(axis: np.ndarray, angle: float) -> np.ndarray:
    """(x, y, z, w) of a rotation by ``angle`` radians about ``axis``."""
    axis = np.asarray(axis, dtype=float)
    axis = axis / np.linalg.norm(axis)
    return np.concatenate([axis * np.sin(angle / 2), [np.cos(angle / 2)]])


def turns_about(axis: np.ndarray, pivot: np.ndarray, start: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """The signed angles (radians, right-handed about the unit ``axis``) by which each of ``ends`` ((3,) or (N, 3))
    stands turned from ``start`` about the line through ``pivot`` along ``axis``, as seen looking down the axis."""
    axis = np.asarray(axis, dtype=float)
    then = np.asarray(start, dtype=float) - pivot
    now = np.asarray(ends, dtype=float) - pivot
    then = then - float(then @ axis) * axis
    now = now - np.asarray(now @ axis)[..., None] * axis
    return np.arctan2(np.cross(then, now) @ axis, now @ then)


def rotation_angle_between(q1: np.ndarray, q2: np.ndarray) -> float:
    """Smallest angle in radians that rotates orientation ``q1`` into ``q2`` (both xyzw)."""
    dot = abs(float(np.dot(np.asarray(q1) / np.linalg.norm(q1), np.asarray(q2) / np.linalg.norm(q2))))
    return 2.0 * float(np.arccos(min(1.0, dot)))


@dataclass(frozen=True)
class Transform:
    """A rigid transform: ``position`` in metres, ``quaternion`` as (x, y, z, w)."""

    position: np.ndarray
    quaternion: np.ndarray

    @staticmethod
    def identity() -> Transform:
        return Transform(np.zeros(3), np.array([0.0, 0.0, 0.0, 1.0]))

    @staticmethod
    def from_matrix(matrix: np.ndarray) -> Transform:
        matrix = np.asarray(matrix, dtype=float)
        return Transform(matrix[:3, 3].copy(), matrix_to_quat(matrix[:3, :3]))

    @staticmethod
    def from_mujoco(position: np.ndarray, quat_wxyz: np.ndarray) -> Transform:
        return Transform(np.array(position, dtype=float), quat_from_mujoco(quat_wxyz))

    @staticmethod
    def from_rotation(position: np.ndarray, rotation: np.ndarray) -> Transform:
        """From a position and a 3x3 rotation matrix."""
        return Transform(np.array(position, dtype=float), matrix_to_quat(np.asarray(rotation, dtype=float)))

    @property
    def rotation(self) -> np.ndarray:
        return quat_to_matrix(self.quaternion)

    def matrix(self) -> np.ndarray:
        out = np.eye(4)
        out[:3, :3] = self.rotation
        out[:3, 3] = self.position
        return out

    def compose(self, other: Transform) -> Transform:
        """``self * other``: ``other`` expressed in the frame of ``self``."""
        return Transform.from_matrix(self.matrix() @ other.matrix())

    def inverse(self) -> Transform:
        return Transform.from_matrix(np.linalg.inv(self.matrix()))

    def apply(self, points: np.ndarray) -> np.ndarray:
        """Transforms points of shape (3,) or (N, 3)."""
        points = np.asarray(points, dtype=float)
        return points @ self.rotation.T + self.position


@dataclass(frozen=True)
class Box3D:
    """Axis-aligned box; :meth:`as_array` gives the API's ``[x_min, y_min, z_min, x_max, y_max, z_max]``."""

    lower: np.ndarray
    upper: np.ndarray

    @staticmethod
    def from_points(points: np.ndarray) -> Box3D:
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        return Box3D(points.min(axis=0), points.max(axis=0))

    @property
    def center(self) -> np.ndarray:
        return (self.lower + self.upper) / 2

    @property
    def size(self) -> np.ndarray:
        return self.upper - self.lower

    @property
    def volume(self) -> float:
        return float(np.prod(np.maximum(self.size, 0.0)))

    def as_array(self) -> np.ndarray:
        return np.concatenate([self.lower, self.upper])

    def corners(self) -> np.ndarray:
        """The eight corners, shape (8, 3)."""
        bounds = np.stack([self.lower, self.upper])
        return np.array([[bounds[i, 0], bounds[j, 1], bounds[k, 2]] for i in (0, 1) for j in (0, 1) for k in (0, 1)])

    def intersection(self, other: Box3D) -> Box3D:
        return Box3D(np.maximum(self.lower, other.lower), np.minimum(self.upper, other.upper))

    def iou(self, other: Box3D) -> float:
        """Intersection over union of the two boxes' volumes (0 where they do not meet)."""
        inter = self.intersection(other).volume
        union = self.volume + other.volume - inter
        return inter / union if union > 0 else 0.0

    def union(self, other: Box3D) -> Box3D:
        return Box3D(np.minimum(self.lower, other.lower), np.maximum(self.upper, other.upper))

    def contains(self, point: np.ndarray) -> bool:
        point = np.asarray(point)
        return bool(np.all(point >= self.lower) and np.all(point <= self.upper))
