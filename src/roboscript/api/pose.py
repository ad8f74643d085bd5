"""``Pose``: the pose type programs use, shaped like ROS ``geometry_msgs/Pose``.

Programs written for the original system build poses field by field (``pose.position.x = 0.3``) and read them the
same way, so the fields are plain assignable floats. Conversions to and from numpy and :class:`Transform` make it
easy to use from this project's code. Quaternions are (x, y, z, w), as in ROS.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.api.arguments import ArgumentTypeError, real, within_world
from roboscript.geometry import Transform, matrix_to_quat, quat_to_matrix


class _Sealed(type):
    """The API's value types cannot be changed: a program that replaced a method or a property of ``Pose`` would
    change what every pose says of itself, in its own process and in what it hands the tools."""

    def __setattr__(cls, name: str, value: object) -> None:
        raise TypeError(f"{cls.__name__}'s methods and properties cannot be changed (tried {name!r})")

    def __delattr__(cls, name: str) -> None:
        raise TypeError(f"{cls.__name__}'s methods and properties cannot be changed (tried {name!r})")


class Point(metaclass=_Sealed):
    """A position in metres: ``x``, ``y``, ``z``."""

    __slots__ = ("_x", "_y", "_z")

    def __init__(self, x: float = 0.0, y: float = 0.0, z: float = 0.0):
        self.x, self.y, self.z = x, y, z

    x = property(lambda self: self._x, lambda self, v: setattr(self, "_x", real(v, "position.x")))
    y = property(lambda self: self._y, lambda self, v: setattr(self, "_y", real(v, "position.y")))
    z = property(lambda self: self._z, lambda self, v: setattr(self, "_z", real(v, "position.z")))

    def to_numpy(self) -> np.ndarray:
        return np.array([self._x, self._y, self._z])

    def __iter__(self):
        return iter((self._x, self._y, self._z))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Point) and tuple(self) == tuple(other)

    def __repr__(self) -> str:
        return f"Point(x={self._x:.4f}, y={self._y:.4f}, z={self._z:.4f})"


class Quaternion(metaclass=_Sealed):
    """An orientation as a quaternion ``(x, y, z, w)``; ``Quaternion()`` is the identity."""

    __slots__ = ("_w", "_x", "_y", "_z")

    def __init__(self, x: float = 0.0, y: float = 0.0, z: float = 0.0, w: float = 1.0):
        self.x, self.y, self.z, self.w = x, y, z, w

    x = property(lambda self: self._x, lambda self, v: setattr(self, "_x", real(v, "orientation.x")))
    y = property(lambda self: self._y, lambda self, v: setattr(self, "_y", real(v, "orientation.y")))
    z = property(lambda self: self._z, lambda self, v: setattr(self, "_z", real(v, "orientation.z")))
    w = property(lambda self: self._w, lambda self, v: setattr(self, "_w", real(v, "orientation.w")))

    def to_numpy(self) -> np.ndarray:
        return np.array([self._x, self._y, self._z, self._w])

    def __iter__(self):
        return iter((self._x, self._y, self._z, self._w))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Quaternion) and tuple(self) == tuple(other)

    def __repr__(self) -> str:
        return f"Quaternion(x={self._x:.4f}, y={self._y:.4f}, z={self._z:.4f}, w={self._w:.4f})"


class Pose(metaclass=_Sealed):
    """A pose like ROS ``geometry_msgs/Pose``: ``Pose()`` is the identity at the origin.

    ``pose.position.x`` and ``pose.orientation.w`` (and the other fields) can be read and assigned. For gripper
    poses the position is the tool centre point and the approach direction is the local +z axis.
    """

    __slots__ = ("_orientation", "_position")

    def __init__(
        self, position: Point | Sequence[float] | None = None, orientation: Quaternion | Sequence[float] | None = None
    ):
        self.position = Point() if position is None else position
        self.orientation = Quaternion() if orientation is None else orientation

    @property
    def position(self) -> Point:
        return self._position

    @position.setter
    def position(self, value: Point | Sequence[float]) -> None:
        if isinstance(value, Point):
            self._position = value
            return
        values = _vector(value, 3, "position")
        self._position = Point(*values)

    @property
    def orientation(self) -> Quaternion:
        return self._orientation

    @orientation.setter
    def orientation(self, value: Quaternion | Sequence[float]) -> None:
        if isinstance(value, Quaternion):
            self._orientation = value
            return
        self._orientation = Quaternion(*_vector(value, 4, "orientation"))

    # --- conversions ---

    @classmethod
    def from_numpy(cls, position: Sequence[float], quaternion: Sequence[float] = (0.0, 0.0, 0.0, 1.0)) -> Pose:
        """From a position (3,) and an (x, y, z, w) quaternion (4,)."""
        return cls(position, quaternion)

    @classmethod
    def from_matrix(cls, matrix: np.ndarray) -> Pose:
        """From a 4x4 homogeneous transform."""
        matrix = np.asarray(matrix, dtype=float)
        if matrix.shape != (4, 4):
            raise ValueError(f"a pose matrix must be 4x4, got shape {matrix.shape}")
        return cls(matrix[:3, 3], matrix_to_quat(matrix[:3, :3]))

    @classmethod
    def from_transform(cls, transform: Transform) -> Pose:
        return cls(transform.position, transform.quaternion)

    def position_array(self) -> np.ndarray:
        return self._position.to_numpy()

    def quaternion_array(self) -> np.ndarray:
        """The orientation as (x, y, z, w), normalised; raises if it is zero."""
        q = self._orientation.to_numpy()
        norm = float(np.linalg.norm(q))
        if norm < 1e-9:
            raise ValueError("the pose's orientation quaternion is zero; set orientation.w = 1 for no rotation")
        return q / norm

    def rotation_matrix(self) -> np.ndarray:
        return quat_to_matrix(self.quaternion_array())

    def to_matrix(self) -> np.ndarray:
        matrix = np.eye(4)
        matrix[:3, :3] = self.rotation_matrix()
        matrix[:3, 3] = self.position_array()
        return matrix

    def to_transform(self) -> Transform:
        return Transform(self.position_array(), self.quaternion_array())

    def copy(self) -> Pose:
        return Pose(tuple(self._position), tuple(self._orientation))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Pose) and self._position == other._position and self._orientation == other._orientation

    def __repr__(self) -> str:
        return f"Pose(position={self._position!r}, orientation={self._orientation!r})"


def _vector(value: object, n: int, field: str) -> np.ndarray:
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{field} must be {n} numbers, got {type(value).__name__} {value!r}") from None
    if array.shape != (n,):
        raise ValueError(f"{field} must be {n} numbers, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{field} must be finite, got {array.tolist()}")
    return array


def pose_argument(value: object, field: str) -> Transform:
    """A tool's Pose argument as a transform, within reach of bounded work (:func:`within_world`)."""
    if not isinstance(value, Pose):
        raise ArgumentTypeError(
            f"{field} must be a Pose (e.g. from get_gripper_pose() or a parse_* tool), got {type(value).__name__}"
        )
    within_world(value.position_array(), field)
    return value.to_transform()


def pose_list(value: object, field: str) -> list[Transform]:
    """A tool's non-empty list of Poses as transforms (:func:`pose_argument` each)."""
    if isinstance(value, Pose) or not isinstance(value, (list, tuple)) or not value:
        raise ArgumentTypeError(f"{field} must be a non-empty list of Pose, got {type(value).__name__}")
    return [pose_argument(p, f"{field}[{i}]") for i, p in enumerate(value)]
