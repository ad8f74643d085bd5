"""Typed planning failures. Each says why it failed and carries the figures a caller can act on."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.errors import FailureError, UsageError


class PlanningError(FailureError, RuntimeError):
    """Base class of every planning failure."""


class IKError(PlanningError):
    """No joint configuration puts the TCP at the target (within tolerance, limits and collision-free)."""

    def __init__(
        self,
        target_position: np.ndarray,
        position_error: float,
        angle_error: float,
        reason: str,
        colliding: Sequence[tuple[str, str]] = (),
    ):
        self.target_position = np.asarray(target_position, dtype=float)
        self.position_error = float(position_error)  # of the nearest pose reached, metres
        self.angle_error = float(angle_error)  # of the nearest pose reached, radians
        self.colliding = tuple(colliding)
        p = ", ".join(f"{v:.3f}" for v in self.target_position)
        message = (
            f"no IK solution for the TCP at [{p}]: {reason}; the nearest pose reached was "
            f"{self.position_error * 100:.1f} cm and {np.degrees(self.angle_error):.1f} deg away"
        )
        if self.colliding:
            message += "; solutions that reached it collide: " + ", ".join(f"{a} with {b}" for a, b in self.colliding)
        super().__init__(message)


class StateInCollisionError(PlanningError):
    """The start or goal configuration collides; ``pairs`` names the bodies in contact."""

    def __init__(self, which: str, pairs: Sequence[tuple[str, str]]):
        self.which = which
        self.pairs = tuple(pairs)
        listed = ", ".join(f"{a} with {b}" for a, b in self.pairs[:6])
        more = f" (and {len(self.pairs) - 6} more)" if len(self.pairs) > 6 else ""
        super().__init__(f"the {which} configuration is in collision: {listed}{more}")


class PlannerTimeoutError(PlanningError):
    """The planner found no path within its time budget."""

    def __init__(self, planner: str, timeout: float):
        self.planner, self.timeout = planner, timeout
        super().__init__(
            f"{planner} found no collision-free path within {timeout:.2f} s; the goal may be enclosed by "
            "obstacles, or give the planner more time"
        )


class PathInCollisionError(PlanningError):
    """A path failed dense validation (should not happen for planner output; raised rather than executed)."""

    def __init__(self, segment: int, count: int, pairs: Sequence[tuple[str, str]]):
        self.segment, self.count, self.pairs = segment, count, tuple(pairs)
        listed = ", ".join(f"{a} with {b}" for a, b in self.pairs[:4]) or "a joint limit"
        super().__init__(f"the path collides in its segment {segment + 1} of {count}: {listed}")


class CartesianPathIncompleteError(PlanningError):
    """A straight-line (Cartesian) path could be followed only for ``fraction`` of its length."""

    def __init__(self, fraction: float, reason: str):
        self.fraction = float(fraction)
        self.reason = reason
        super().__init__(f"the Cartesian path is only {self.fraction:.0%} achievable: {reason}")


class UnknownPlannerError(UsageError, ValueError):
    def __init__(self, name: str, available: Sequence[str], unavailable: dict[str, str]):
        self.name = name
        message = f"unknown planner {name!r}; available: {', '.join(available)}"
        if name in unavailable:
            message = f"planner {name!r} is not available: {unavailable[name]}; available: {', '.join(available)}"
        super().__init__(message)


class TrackingError(PlanningError):
    """The arm did not follow the executed trajectory (it was blocked, or pushed something heavy)."""

    def __init__(self, max_tcp_error: float, tolerance: float):
        self.max_tcp_error, self.tolerance = max_tcp_error, tolerance
        super().__init__(
            f"the TCP strayed {max_tcp_error * 100:.1f} cm from the planned trajectory (tolerance "
            f"{tolerance * 100:.1f} cm): something unplanned blocked the arm"
        )
