"""Time parameterisation of a joint path within per-joint velocity and acceleration limits.

The path is followed as given: it is cut into short straight pieces and the speed along it is the fastest profile
that keeps every joint within its limits (a forward-backward pass over the pieces, as in time-optimal path
parameterisation on a discretised path). Corners are taken at a speed that turns within the acceleration limits
over one piece, so the trajectory stays within a fraction of a piece of the validated polyline.

Neither ruckig (its open-source edition has no intermediate waypoints) nor toppra (which pulls in matplotlib and
fits a spline that leaves the validated path) is used: what is executed must be the path that was checked.
"""

from __future__ import annotations

import numpy as np

from roboscript.trajectory import JointTrajectory, scaled_limits

_SHARP_TURN = 2 * np.sin(np.radians(10) / 2)  # chord between unit tangents 10 degrees apart


def resample_polyline(waypoints: np.ndarray, max_step: float) -> np.ndarray:
    """The polyline with points added so that no joint moves more than ``max_step`` between two; drops repeats."""
    waypoints = np.atleast_2d(np.asarray(waypoints, dtype=float))
    out = [waypoints[0]]
    for b in waypoints[1:]:
        a = out[-1]
        largest = float(np.max(np.abs(b - a)))
        if largest < 1e-12:
            continue
        n = max(1, int(np.ceil(largest / max_step)))
        out.extend(a + (b - a) * (k / n) for k in range(1, n + 1))
    return np.array(out)


def time_parameterize(
    waypoints: np.ndarray,
    max_velocity: np.ndarray,
    max_acceleration: np.ndarray,
    speed_scale: float = 1.0,
    max_step: float = 0.02,
) -> JointTrajectory:
    """A trajectory along ``waypoints`` (N, dof), from rest to rest, within ``speed_scale`` times the limits."""
    vmax, amax = scaled_limits(max_velocity, max_acceleration, speed_scale)
    points = resample_polyline(waypoints, max_step)
    if len(points) < 2:
        dof = points.shape[1]
        return JointTrajectory(np.array([0.0, 1e-3]), np.repeat(points, 2, axis=0), np.zeros((2, dof)))

    deltas = np.diff(points, axis=0)
    lengths = np.linalg.norm(deltas, axis=1)
    tangents = deltas / lengths[:, None]
    with np.errstate(divide="ignore"):
        segment_speed = np.min(vmax / np.abs(tangents), axis=1)
        segment_accel = np.min(amax / np.abs(tangents), axis=1)

    n = len(points)
    speed = np.zeros(n)
    speed[1:-1] = np.minimum(segment_speed[:-1], segment_speed[1:])
    turn = np.abs(tangents[1:] - tangents[:-1])  # change of direction at each interior point
    reach = np.minimum(lengths[:-1], lengths[1:])
    with np.errstate(divide="ignore", invalid="ignore"):
        # Turning within one piece needs v^2 |turn| / reach <= amax; the cubic between knots peaks at about three
        # times its mean acceleration, hence the factor. Sharp corners (a planner's) are taken from rest.
        corner = np.sqrt(np.min(amax[None, :] * reach[:, None] / (3.0 * turn), axis=1))
    corner = np.nan_to_num(corner, nan=np.inf, posinf=np.inf)
    corner[np.linalg.norm(tangents[1:] - tangents[:-1], axis=1) > _SHARP_TURN] = 0.0
    speed[1:-1] = np.minimum(speed[1:-1], corner)

    for k in range(n - 1):  # accelerate no faster than the limits allow
        speed[k + 1] = min(speed[k + 1], np.sqrt(speed[k] ** 2 + 2 * segment_accel[k] * lengths[k]))
    for k in range(n - 2, -1, -1):  # and brake in time
        speed[k] = min(speed[k], np.sqrt(speed[k + 1] ** 2 + 2 * segment_accel[k] * lengths[k]))

    pair = speed[:-1] + speed[1:]
    # A piece between two rests (two sharp corners closer than max_step) is a cubic whose peak acceleration is
    # 6 L / T^2; otherwise the speed changes at a constant rate along the piece.
    with np.errstate(divide="ignore"):
        durations = np.where(pair > 0, 2 * lengths / pair, 2 * np.sqrt(1.5 * lengths / segment_accel))
    times = np.concatenate([[0.0], np.cumsum(durations)])
    directions = np.zeros_like(points)
    directions[0], directions[-1] = tangents[0], tangents[-1]
    mean = tangents[:-1] + tangents[1:]
    directions[1:-1] = mean / np.maximum(np.linalg.norm(mean, axis=1, keepdims=True), 1e-12)
    velocities = directions * speed[:, None]
    return JointTrajectory(times, points, velocities)
