"""Joint trajectories as time-stamped points, the form a real arm's trajectory controller accepts.

A :class:`JointTrajectory` holds positions and velocities at increasing times and is sampled by cubic Hermite
interpolation between them; :func:`roboscript.planning.timing.time_parameterize` makes one along a planned path
within per-joint velocity and acceleration limits.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class JointTrajectory:
    """``positions[i]`` and ``velocities[i]`` are the targets at ``times[i]`` seconds from the start."""

    times: np.ndarray  # (N,)
    positions: np.ndarray  # (N, dof)
    velocities: np.ndarray  # (N, dof)

    def __post_init__(self) -> None:
        times = np.asarray(self.times, dtype=float)
        positions = np.atleast_2d(np.asarray(self.positions, dtype=float))
        velocities = np.atleast_2d(np.asarray(self.velocities, dtype=float))
        if times.ndim != 1 or len(times) < 1:
            raise ValueError("a trajectory needs at least one time stamp")
        if positions.shape[0] != len(times) or velocities.shape != positions.shape:
            raise ValueError(
                f"trajectory shapes disagree: {len(times)} times, positions {positions.shape}, "
                f"velocities {velocities.shape}"
            )
        if np.any(np.diff(times) <= 0):
            raise ValueError("trajectory times must increase strictly")
        if not (np.all(np.isfinite(positions)) and np.all(np.isfinite(velocities))):
            raise ValueError("trajectory holds non-finite values")
        object.__setattr__(self, "times", times)
        object.__setattr__(self, "positions", positions)
        object.__setattr__(self, "velocities", velocities)

    @property
    def duration(self) -> float:
        return float(self.times[-1])

    @property
    def dof(self) -> int:
        return self.positions.shape[1]

    def sample_many(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Positions, velocities and accelerations at many times at once, each (len(t), dof)."""
        t = np.clip(np.asarray(t, dtype=float), self.times[0], self.times[-1])
        if len(self.times) == 1:
            n = len(t)
            return np.repeat(self.positions, n, axis=0), np.zeros((n, self.dof)), np.zeros((n, self.dof))
        i = np.clip(np.searchsorted(self.times, t, side="right") - 1, 0, len(self.times) - 2)
        h = (self.times[i + 1] - self.times[i])[:, None]
        u = ((t - self.times[i])[:, None]) / h
        p0, p1 = self.positions[i], self.positions[i + 1]
        m0, m1 = self.velocities[i] * h, self.velocities[i + 1] * h
        u2, u3 = u * u, u * u * u
        q = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1
        dq = ((6 * u2 - 6 * u) * p0 + (3 * u2 - 4 * u + 1) * m0 + (-6 * u2 + 6 * u) * p1 + (3 * u2 - 2 * u) * m1) / h
        ddq = ((12 * u - 6) * p0 + (6 * u - 4) * m0 + (-12 * u + 6) * p1 + (6 * u - 2) * m1) / (h * h)
        at_end = t >= self.times[-1]
        dq[at_end] = 0.0
        ddq[at_end] = 0.0
        return q, dq, ddq

    def sample(self, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity and acceleration at time ``t`` (clamped to the trajectory's span)."""
        q, dq, ddq = self.sample_many(np.array([t]))
        if t <= self.times[0]:
            return q[0], np.zeros(self.dof), np.zeros(self.dof)
        return q[0], dq[0], ddq[0]


def scaled_limits(
    max_velocity: np.ndarray, max_acceleration: np.ndarray, speed_scale: float
) -> tuple[np.ndarray, np.ndarray]:
    """Per-joint velocity and acceleration limits scaled by ``speed_scale``, which must be in (0, 1]."""
    if not 0 < speed_scale <= 1:
        raise ValueError(f"speed_scale must be in (0, 1], got {speed_scale}")
    return np.asarray(max_velocity, dtype=float) * speed_scale, np.asarray(max_acceleration, dtype=float) * speed_scale
