"""Collision-aware inverse kinematics: several seeds, solutions within limits, the nearest free one chosen."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.geometry import Transform
from roboscript.planning.errors import IKError
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.scene import PlanningScene


def solve_ik(
    kinematics: ArmKinematics,
    target: Transform,
    reference: np.ndarray,
    scene: PlanningScene | None = None,
    attempts: int = 16,
    max_attempts: int = 150,
    wanted_solutions: int = 3,
    seed: int = 0,
) -> np.ndarray:
    """A joint configuration that puts the TCP at ``target``, collision-free in ``scene`` if one is given.

    The first seed is ``reference`` (usually the current configuration), the others are drawn uniformly within
    the joint limits (deterministically, from ``seed``). After ``attempts`` seeds the search stops if it has a
    solution, else goes on up to ``max_attempts`` (a redundant arm may have free solutions on few branches only).
    Among the solutions found, the one nearest ``reference`` is returned. Raises :class:`IKError` with the
    nearest pose reached, or with the collisions of the solutions.
    """
    return ik_solutions(kinematics, target, reference, scene, attempts, max_attempts, wanted_solutions, seed)[0]


def ik_solutions(
    kinematics: ArmKinematics,
    target: Transform,
    reference: np.ndarray,
    scene: PlanningScene | None = None,
    attempts: int = 16,
    max_attempts: int = 150,
    wanted_solutions: int = 3,
    seed: int = 0,
    seeds: Sequence[np.ndarray] = (),
) -> list[np.ndarray]:
    """Up to ``wanted_solutions`` collision-free solutions, nearest ``reference`` first; see :func:`solve_ik`.
    ``seeds``: configurations tried right after ``reference``, before the random ones (near the edge of the
    arm's reach, random seeds may all miss a pose that a configuration chosen for a pose nearby reaches)."""
    reference = np.asarray(reference, dtype=float)
    rng = np.random.default_rng(seed)
    starts = [reference, *(np.asarray(q, dtype=float) for q in seeds)]
    solutions: list[np.ndarray] = []
    colliding: list[tuple[str, str]] = []
    best_position, best_angle = np.inf, np.inf
    extra = len(starts) - 1  # the reference counts among the attempts, the seeds do not
    for attempt in range(max(attempts, max_attempts) + extra):
        if attempt >= attempts + extra and solutions:
            break
        start = starts[attempt] if attempt < len(starts) else rng.uniform(kinematics.lower, kinematics.upper)
        result = kinematics.solve(target, start)
        if result.position_error + 0.1 * result.angle_error < best_position + 0.1 * best_angle:
            best_position, best_angle = result.position_error, result.angle_error
        if not result.converged:
            continue
        q = _nearest_equivalent(result.q, reference, kinematics.lower, kinematics.upper)
        if scene is not None and not scene.is_valid(q):
            for pair in scene.collisions(q):
                if pair not in colliding:
                    colliding.append(pair)
            continue
        if any(np.allclose(q, other, atol=1e-3) for other in solutions):
            continue
        solutions.append(q)
        if len(solutions) >= wanted_solutions:
            break
    if solutions:
        return sorted(solutions, key=lambda q: float(np.sum((q - reference) ** 2)))
    if colliding:
        raise IKError(target.position, best_position, best_angle, "every solution found is in collision", colliding)
    raise IKError(
        target.position,
        best_position,
        best_angle,
        f"not reachable within the joint limits ({max(attempts, max_attempts)} seeds)",
    )


def _nearest_equivalent(q: np.ndarray, reference: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Moves joints by whole turns towards ``reference`` where the limits allow (wrist joints with +-2 pi range)."""
    q = q.copy()
    for j in range(len(q)):
        for shift in (-2 * np.pi, 2 * np.pi):
            candidate = q[j] + shift
            if lower[j] <= candidate <= upper[j] and abs(candidate - reference[j]) < abs(q[j] - reference[j]):
                q[j] = candidate
    return q
