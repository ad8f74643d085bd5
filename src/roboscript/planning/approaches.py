"""Straight approaches to a pose (a grasp, a place): the TCP comes in along its own z for the last stretch, as
MoveIt's pick and place pipelines approach. An approach is found backwards from the target's IK branches, then
the arm is planned to the start of the first one a path reaches and goes in along it."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Transform
from roboscript.planning.cartesian import cartesian_path
from roboscript.planning.errors import IKError
from roboscript.planning.ik import IKSearch, ik_solutions
from roboscript.planning.motion import MotionPlanner

APPROACH_SEARCH = IKSearch(solutions=4)  # the IK branches whose straight approach lines are tried
WIDE_APPROACH_SEARCH = IKSearch(8, 80, 8)  # see approaches
MIN_APPROACH_FRACTION = 0.5  # of the pre-grasp distance: the least straight approach a grasp is moved in along
APPROACH_FRACTIONS = (1.0, 0.5, 0.25, 0.125)  # of the pre-grasp distance: where a way in with no clear line may start


def straight_lines(
    motion: MotionPlanner, target: Transform, distance: float, reference: np.ndarray, search: IKSearch, first: bool
) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """Configurations at ``target``, each with a straight approach to it from ``distance`` back along the
    TCP's z, nearest ``reference`` first.

    An approach is found backwards, by backing out of the target along the line, so that it ends on the
    target's own IK branch: a configuration solved for the start of the line on its own may sit on another
    branch, from which no straight line leads to the target. Near a singularity (the hand above the base)
    some branches cannot follow the line at all, so up to ``search.solutions`` IK solutions are tried. Returns those
    whose line is clear (with ``first``, the first such; the configuration preferred for ``target``, if one is,
    first of all), with its joint waypoints; where none is, the longest
    line clear for at least :data:`MIN_APPROACH_FRACTION` of ``distance``; or, when every line is blocked
    sooner, the nearest solution with None. Raises :class:`IKError` if ``target`` has no solution.
    """
    solutions = ik_solutions(motion.kinematics, target, reference, motion.scene, search)
    preferred = motion.preferences.preferred_for(target, motion.scene.is_valid)
    if preferred is not None:  # chosen for what follows the grasp (a handle's branch that can swing its door)
        solutions = [preferred, *solutions]
    start = Transform(target.position - distance * target.rotation[:, 2], target.quaternion)
    found = []
    shorter: tuple[float, np.ndarray, np.ndarray] | None = None
    for q in solutions:
        line = cartesian_path(motion.kinematics, motion.scene, q, [start])
        if line.fraction >= 1.0:
            found.append((q, line.waypoints[::-1].copy()))
            if first:
                break
        elif line.fraction >= MIN_APPROACH_FRACTION and (shorter is None or line.fraction > shorter[0]):
            shorter = (line.fraction, q, line.waypoints[::-1].copy())
    if not found and shorter is not None:
        # As MoveIt's pick has a desired and a least approach distance: a pre-grasp pose at the edge of reach
        # (a handle met head-on) is moved in along the line as far as it is free.
        found.append(shorter[1:])
    return found or [(solutions[0], None)]


def approaches(
    motion: MotionPlanner,
    target: Transform,
    distance: float,
    reference: np.ndarray | None = None,
    search: IKSearch = APPROACH_SEARCH,
    first: bool = False,
) -> list[tuple[np.ndarray, np.ndarray | None]]:
    """Configurations at ``target``, each with a straight approach to it from ``distance`` back along the TCP's z
    (:func:`straight_lines`, from the present configuration by default), searching
    :data:`WIDE_APPROACH_SEARCH`'s IK branches where the nearest have no clear line of the full ``distance``: they
    may all be walled in (an arm that has just put something down beside the cabinet)."""
    reference = motion.sync() if reference is None else reference
    options = straight_lines(motion, target, distance, reference, search, first)
    if approach_length(motion, options[0][1]) < distance - 1e-3:
        wider = straight_lines(motion, target, distance, reference, WIDE_APPROACH_SEARCH, first)
        if approach_length(motion, wider[0][1]) > approach_length(motion, options[0][1]):
            options = wider
    return options


def approach_length(motion: MotionPlanner, line: np.ndarray | None) -> float:
    """How far a straight approach's line (joint waypoints) moves the TCP; 0 for none."""
    if line is None:
        return 0.0
    return float(np.linalg.norm(motion.kinematics.fk(line[0]).position - motion.kinematics.fk(line[-1]).position))


def move_to_approach(
    motion: MotionPlanner, options: list[tuple[np.ndarray, np.ndarray | None]], target: Transform, distance: float
) -> tuple[np.ndarray, np.ndarray | None]:
    """Moves to the start of whichever of ``options`` (from :func:`approaches`) a planned path reaches: each IK
    branch with a clear line is a goal, so where none leads to one branch's start (walled in by the table on a
    6-joint arm) the next is tried. Returns that option."""
    starts: list[tuple[int, np.ndarray]] = []
    failure: IKError | None = None
    for index, (goal, line) in enumerate(options):
        if line is not None:
            starts.append((index, line[0]))
            continue
        try:
            starts.append((index, _approach_start(motion, target, distance, goal)))
        except IKError as exc:  # this branch's way in starts out of reach; another's may not
            failure = failure or exc
    if failure is not None and not starts:
        raise failure
    return options[starts[motion.move_to_any([q for _, q in starts])][0]]


def _approach_start(motion: MotionPlanner, target: Transform, distance: float, goal: np.ndarray) -> np.ndarray:
    """Where an approach with no clear straight line starts: the pre-grasp ``distance`` back along the
    approach axis, or a half, a quarter, an eighth as far where that is out of reach (a handle at the edge of the
    arm's reach: a door's handle swung 60 degrees towards a Panda was out of reach from 5 cm back, not from 2.5)."""
    axis = target.rotation[:, 2]
    for fraction in APPROACH_FRACTIONS:
        try:
            return motion.ik(Transform(target.position - fraction * distance * axis, target.quaternion), goal)
        except IKError as exc:
            failure = exc
    raise failure


def finish_approach(motion: MotionPlanner, option: tuple[np.ndarray, np.ndarray | None], target: Transform) -> None:
    """Moves in along the option's straight line to ``target``; where it had none, or the line is blocked now
    (the world moved), straight if that has become feasible, else planned."""
    goal, line = option
    here = None if line is None else motion.from_here(line)
    if here is not None:
        motion.execute(here)
        return
    straight = motion.cartesian([target])
    motion.execute(straight.waypoints if straight.fraction >= 1.0 else motion.plan_to_joints(goal))
