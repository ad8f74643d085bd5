"""Collision-aware inverse kinematics: several seeds, solutions within limits, the nearest free one chosen."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Transform
from roboscript.planning.errors import IKError
from roboscript.planning.kinematics import ArmKinematics, nearest_equivalent
from roboscript.planning.scene import PlanningScene

TCP_POSE_COLLIDES = "the hand or what it holds collides at this pose, whatever the arm's configuration"


@dataclass(frozen=True)
class IKSearch:
    """How hard an IK search looks: after ``attempts`` seeds it stops if it has a solution, else it goes on up to
    ``max_attempts``; it keeps up to ``solutions`` collision-free solutions (IK branches)."""

    attempts: int = 16
    max_attempts: int = 150
    solutions: int = 3

    def __post_init__(self) -> None:
        if min(self.attempts, self.max_attempts, self.solutions) < 1:
            raise ValueError(f"an IK search needs at least one attempt and one solution, got {self}")


DEFAULT_SEARCH = IKSearch()


def ik_solutions(
    kinematics: ArmKinematics,
    target: Transform,
    reference: np.ndarray,
    scene: PlanningScene | None = None,
    search: IKSearch = DEFAULT_SEARCH,
    seed: int = 0,
    seeds: Sequence[np.ndarray] = (),
) -> list[np.ndarray]:
    """Joint configurations that put the TCP at ``target``, collision-free in ``scene`` if one is given: up to
    ``search.solutions`` of them, nearest ``reference`` first.

    The first seed is ``reference`` (usually the current configuration), then ``seeds`` (near the edge of the arm's
    reach, random seeds may all miss a pose that a configuration chosen for a pose nearby reaches), then seeds drawn
    uniformly within the joint limits (deterministically, from ``seed``), as many as ``search`` says (a redundant
    arm may have free solutions on few branches only). Raises :class:`IKError` with the nearest pose reached, or
    with the collisions of the solutions.

    An arm with a closed form (:attr:`ArmKinematics.closed_form`) has all its solutions at once, and the nearest
    free ones are returned with no seeds drawn. Where it has none within the limits and tolerances, one iterative
    run from ``reference`` decides a pose at the very edge of reach and says how near the arm came: a hundred
    random seeds could find nothing the closed form missed."""
    reference = np.asarray(reference, dtype=float)
    attempts, max_attempts, wanted_solutions = search.attempts, search.max_attempts, search.solutions
    if kinematics.closed_form is not None:
        found = _closed_form_solutions(kinematics, target, reference, scene, wanted_solutions)
        if found:
            return found
        attempts = max_attempts = 1
        seeds = ()
    searched = f"{max(attempts, max_attempts)} seeds"
    if kinematics.closed_form is not None:
        searched = "no closed-form solution"
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
        q = nearest_equivalent(result.q, reference, kinematics.lower, kinematics.upper)
        if scene is not None and not scene.is_valid(q):
            for pair in scene.collisions(q):
                if pair not in colliding:
                    colliding.append(pair)
            if not solutions and scene.collides_wherever_the_tcp_is(q):
                # The hand (or what it holds) collides at the pose itself: no other seed can help.
                raise IKError(target.position, 0.0, 0.0, TCP_POSE_COLLIDES, colliding)
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
        f"not reachable within the joint limits ({searched})",
    )


def _closed_form_solutions(
    kinematics: ArmKinematics,
    target: Transform,
    reference: np.ndarray,
    scene: PlanningScene | None,
    wanted: int,
) -> list[np.ndarray]:
    """The closed form's collision-free solutions, nearest ``reference`` first, at most ``wanted``. Raises
    :class:`IKError` with the collisions if it has solutions but every one collides."""
    results = kinematics.closed_form_solutions(target, reference)
    solutions: list[np.ndarray] = []
    colliding: list[tuple[str, str]] = []
    for result in sorted(results, key=lambda r: float(np.sum((r.q - reference) ** 2))):
        q = result.q
        if scene is not None and not scene.is_valid(q):
            colliding.extend(pair for pair in scene.collisions(q) if pair not in colliding)
            if scene.collides_wherever_the_tcp_is(q):
                break
            continue
        if any(np.allclose(q, other, atol=1e-3) for other in solutions):
            continue
        solutions.append(q)
        if len(solutions) >= wanted:
            break
    if not solutions and colliding:
        raise IKError(target.position, 0.0, 0.0, "every solution is in collision", colliding)
    return solutions
