"""Cartesian paths: the TCP along straight lines through poses, or along an arc about a revolute joint.

Like MoveIt's ``computeCartesianPath``, following stops at the first pose that cannot be reached continuously and
collision-free, and the achieved fraction of the path is returned with the reason it stopped.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Transform, quat_from_axis_angle, rotation_angle_between
from roboscript.phases import timed
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.path_checks import first_blocked
from roboscript.planning.scene import PlanningScene


@dataclass(frozen=True)
class CartesianResult:
    """Joint waypoints of the part of the path achieved, the fraction achieved, and why it stopped short."""

    waypoints: np.ndarray  # (N, dof), starting at the start configuration
    fraction: float
    reason: str = ""  # empty when the whole path was achieved


def interpolate_poses(
    start: Transform, goal: Transform, max_step: float, max_angle: float, min_steps: int = 1
) -> list[Transform]:
    """Poses from ``start`` (excluded) to ``goal`` (included), at least ``min_steps``: position linear,
    orientation by slerp."""
    distance = float(np.linalg.norm(goal.position - start.position))
    angle = rotation_angle_between(start.quaternion, goal.quaternion)
    n = max(min_steps, int(np.ceil(max(distance / max_step, angle / max_angle))))
    return [
        Transform(
            start.position + (goal.position - start.position) * (k / n),
            _slerp(start.quaternion, goal.quaternion, k / n),
        )
        for k in range(1, n + 1)
    ]


def _slerp(q0: np.ndarray, q1: np.ndarray, u: float) -> np.ndarray:
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    dot = float(np.dot(q0, q1))
    if dot < 0:
        q1, dot = -q1, -dot
    if dot > 0.9995:
        q = q0 + u * (q1 - q0)
        return q / np.linalg.norm(q)
    theta = np.arccos(dot)
    return (np.sin((1 - u) * theta) * q0 + np.sin(u * theta) * q1) / np.sin(theta)


def arc_poses(current: Transform, axis: np.ndarray, pivot: np.ndarray, n: int, angle: float) -> list[Transform]:
    """``n`` poses turning ``current`` about the line through ``pivot`` along ``axis`` by ``angle`` radians in all.

    Position and orientation turn together, as a hand holding a door handle does.
    """
    if n < 1:
        raise ValueError(f"an arc needs at least one waypoint, got n={n}")
    axis = np.asarray(axis, dtype=float)
    norm = float(np.linalg.norm(axis))
    if norm < 1e-9:
        raise ValueError("the arc's axis must be a non-zero vector")
    axis = axis / norm
    pivot = np.asarray(pivot, dtype=float)
    poses = []
    for k in range(1, n + 1):
        turn = Transform(np.zeros(3), quat_from_axis_angle(axis, angle * k / n))
        rotation = turn.rotation
        position = pivot + rotation @ (current.position - pivot)
        poses.append(Transform(position, turn.compose(Transform(np.zeros(3), current.quaternion)).quaternion))
    return poses


@timed("planning")
def cartesian_path(
    kinematics: ArmKinematics,
    scene: PlanningScene | None,
    start: np.ndarray,
    poses: Sequence[Transform],
    eef_step: float = 0.005,
    max_angle_step: float = np.radians(3.0),
    jump_threshold: float = 0.2,
) -> CartesianResult:
    """Follows straight TCP lines from the pose at ``start`` through ``poses``.

    Each interpolated pose is solved by IK seeded with the previous solution; it counts as reached only if IK
    converges, no joint moves more than ``jump_threshold`` radians in one step (a jump through a singularity or to
    another branch), and the motion to it is collision-free in ``scene`` (when one is given).
    """
    start = np.asarray(start, dtype=float)
    if not poses:
        raise ValueError("a Cartesian path needs at least one pose")
    current_pose = kinematics.fk(start)
    targets: list[Transform] = []
    anchors = [current_pose, *poses]
    for a, b in itertools.pairwise(anchors):
        targets.extend(interpolate_poses(a, b, eef_step, max_angle_step))
    total = _path_measure(current_pose, targets)
    q = start
    waypoints = [start]
    achieved = 0.0
    previous = current_pose
    for target in targets:
        result = kinematics.solve(target, q, max_iterations=30)
        reason = ""
        steps = [result.q]
        if result.converged and float(np.max(np.abs(result.q - q))) > jump_threshold:
            # A fast but continuous turn (a wrist near a singularity) passes in smaller steps; a flip to another
            # branch jumps however small the step.
            steps = _in_smaller_steps(kinematics, previous, target, q, jump_threshold) or steps
        if not result.converged:
            reason = f"no IK solution at [{', '.join(f'{v:.3f}' for v in target.position)}]"
        elif len(steps) == 1 and float(np.max(np.abs(result.q - q))) > jump_threshold:
            j = int(np.argmax(np.abs(result.q - q)))
            reason = f"joint {j + 1} would jump {abs(result.q[j] - q[j]):.2f} rad (near a singularity or a joint limit)"
        elif scene is not None:
            # Each step starts where the one before ended, already checked: only the first step checks its start.
            blocked = first_blocked(scene, np.array([q, *steps]), scene.padding, check_start=len(waypoints) == 1)
            if blocked is not None:
                pairs = scene.collisions(blocked.q)
                if pairs:
                    reason = "collision: " + ", ".join(f"{a} with {b}" for a, b in pairs[:4])
                else:
                    reason = "a joint limit is in the way"
        if reason:
            return CartesianResult(np.array(waypoints), achieved / total if total > 0 else 0.0, reason)
        achieved += _step_measure(previous, target)
        previous = target
        waypoints.extend(steps)
        q = steps[-1]
    return CartesianResult(np.array(waypoints), 1.0)


SUBSTEPS = 5


def _in_smaller_steps(
    kinematics: ArmKinematics, start: Transform, target: Transform, q: np.ndarray, jump_threshold: float
) -> list[np.ndarray] | None:
    """Configurations from ``q`` to ``target`` through :data:`SUBSTEPS` smaller steps, none moving a joint more
    than half ``jump_threshold``; None if a step jumps (a branch flip, not a fast turn) or IK fails."""
    steps = []
    for pose in interpolate_poses(start, target, np.inf, np.inf, SUBSTEPS):
        result = kinematics.solve(pose, q, max_iterations=30)
        if not result.converged or float(np.max(np.abs(result.q - q))) > jump_threshold / 2:
            return None
        q = result.q
        steps.append(q)
    return steps


def _step_measure(a: Transform, b: Transform) -> float:
    """Length of a step: metres, with a radian of turn counted as 0.1 m so pure rotations have a length too."""
    return float(np.linalg.norm(b.position - a.position)) + 0.1 * rotation_angle_between(a.quaternion, b.quaternion)


def _path_measure(start: Transform, targets: list[Transform]) -> float:
    total, previous = 0.0, start
    for target in targets:
        total += _step_measure(previous, target)
        previous = target
    return total
