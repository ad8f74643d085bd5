"""Checks of the tools' arguments: numbers, 3-vectors, directions and poses, each refused with an error that names
the argument, what it was and what would be valid."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Protocol, runtime_checkable

import numpy as np

from roboscript.errors import UsageError

FARTHEST_POSE = 10.0  # metres from the world's origin along any axis: every arm reaches less than one


class ArgumentError(UsageError, ValueError):
    """A tool's argument has a value the tool cannot use (a zero direction, a distance of 5 m)."""


class ArgumentTypeError(ArgumentError, TypeError):
    """A tool's argument is of the wrong type (a name where a list of names goes)."""


@runtime_checkable
class HasPosition(Protocol):
    """What stands for a point as well as three numbers: a Pose."""

    def position_array(self) -> np.ndarray: ...


def real(value: object, field: str) -> float:
    """A finite number."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ArgumentTypeError(f"{field} must be a number, got {type(value).__name__} {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise ArgumentError(f"{field} must be finite, got {value}")
    return value


def vector(value: object, field: str) -> np.ndarray:
    """Three finite numbers ``[x, y, z]`` (a Pose stands for its position)."""
    if isinstance(value, HasPosition):
        return value.position_array()
    if isinstance(value, (str, bytes)) or value is None:
        raise ArgumentTypeError(f"{field} must be 3 numbers [x, y, z], got {type(value).__name__} {value!r}")
    try:
        array = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise ArgumentTypeError(f"{field} must be 3 numbers [x, y, z], got {type(value).__name__} {value!r}") from None
    if array.shape != (3,):
        raise ArgumentError(f"{field} must be 3 numbers [x, y, z], got {array.size}")
    if not np.all(np.isfinite(array)):
        raise ArgumentError(f"{field} must be finite, got {array.tolist()}")
    return array


def direction(value: object, field: str) -> np.ndarray:
    """A non-zero 3-vector, normalised."""
    array = vector(value, field)
    norm = float(np.linalg.norm(array))
    if norm < 1e-9:
        raise ArgumentError(f"{field} must be a non-zero direction, got {array.tolist()}")
    return array / norm


def names(value: object, field: str) -> list[str]:
    """A list of names (a single string is refused: it would be read letter by letter)."""
    if isinstance(value, str) or not isinstance(value, (list, tuple)) or not all(isinstance(n, str) for n in value):
        raise ArgumentTypeError(f"{field} must be a list of names, e.g. ['apple', 'bowl'], got {value!r}")
    return list(value)


def whole(value: object, field: str, least: int, most: int) -> int:
    """A whole number within ``[least, most]``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or not least <= value <= most:
        raise ArgumentError(f"{field} must be a whole number in [{least}, {most}], got {value!r}")
    return int(value)


def one_of(value: object, field: str, choices: tuple[str, ...]) -> str:
    """One of ``choices``."""
    if value not in choices:
        raise ArgumentError(f"{field} must be one of {', '.join(map(repr, choices))}, got {value!r}")
    return str(value)


def within_world(position: np.ndarray, field: str) -> None:
    """A pose's position within :data:`FARTHEST_POSE` of the world's origin: a straight path there is
    interpolated in steps of millimetres, and only bounded work may be asked for."""
    far = float(np.max(np.abs(position)))
    if far > FARTHEST_POSE:
        raise ArgumentError(
            f"{field} is {far:.3g} m from the world's origin; poses are in metres and within {FARTHEST_POSE:g} m of it"
        )


def optional(check: Callable[[object, str], np.ndarray], value: object, field: str) -> np.ndarray | None:
    """``check(value, field)``, or None where the argument was left out."""
    return None if value is None else check(value, field)
