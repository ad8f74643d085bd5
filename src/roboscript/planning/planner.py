"""Joint-space motion planning with OMPL's planners, MuJoCo as the collision checker.

Every returned path has been simplified and then validated densely: consecutive checks are at most
``validation_step`` metres of travel apart for any point of the arm (bounded from where its bodies are at the ends of
each segment: :mod:`roboscript.planning.path_checks`), and the scene's padding is at least that step, so no point of
the arm can pass through an obstacle between two checks.

A goal is a pose of the arm: where a joint can turn more than once (a UR arm's joints have two turns of range), the
path may end at the goal turned a whole turn about such a joint (:func:`whole_turn_equivalents`). A UR5e whose
shoulder housing cannot pan past a basket beside its base reaches the same configuration by panning the other way.
"""

from __future__ import annotations

import itertools
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from roboscript.phases import timed
from roboscript.planning.errors import (
    PathInCollisionError,
    PlannerTimeoutError,
    PlanningError,
    StateInCollisionError,
    UnknownPlannerError,
)
from roboscript.planning.path_checks import first_blocked
from roboscript.planning.roadmap import roadmap_path
from roboscript.planning.scene import PlanningScene

CONSTRAINED_RANGE = 0.5  # radians: the longest step a sampling planner takes under a path constraint

_OMPL = None


def import_ompl():
    """Imports OMPL once, quietly (its log goes to stdout at INFO level by default)."""
    global _OMPL
    if _OMPL is None:
        from ompl import base, geometric, util

        util.setLogLevel(util.LOG_WARN)
        _OMPL = (base, geometric, util)
    return _OMPL


_SEEDED = False


def seed_sampling(seed: int) -> None:
    """Seeds OMPL's random sampling for this process, so that a run can be repeated exactly.

    OMPL fixes its seed when it first samples, so only the first call in a process counts, and only if it comes
    before the first plan (as in each forked benchmark trial); later calls do nothing.
    """
    global _SEEDED
    if not _SEEDED:
        import_ompl()[2].RNG.setSeed(int(seed) % (2**31 - 1) + 1)
        _SEEDED = True


# Name -> OMPL class name. The original system exposed twelve planners through MoveIt; these are the ones the
# ompl 2.0.1 Python wheel binds, under their MoveIt-style names and OMPL's own.
_PLANNER_CLASSES = {
    "RRTConnect": "RRTConnect",
    "RRT": "RRT",
    "RRTstar": "RRTstar",
    "InformedRRTstar": "InformedRRTstar",
    "PRM": "PRM",
    "PRMstar": "PRMstar",
    "BITstar": "BITstar",
    "KPIECE": "KPIECE1",
    "BKPIECE": "BKPIECE1",
    "LBKPIECE": "LBKPIECE1",
    "FMT": "FMT",
    "BFMT": "BFMT",
}
_ALIASES = {"RRT*": "RRTstar", "PRM*": "PRMstar", "BIT*": "BITstar", "KPIECE1": "KPIECE", "BKPIECE1": "BKPIECE"}
_ALIASES.update({"LBKPIECE1": "LBKPIECE"})
_UNAVAILABLE = {
    name: "the ompl 2.0.1 Python bindings do not include it" for name in ("EST", "BiEST", "SBL", "TRRT", "BiTRRT")
}
_UNAVAILABLE["SORRTstar"] = "with ompl 2.0.1 its solve() ignores the time limit"
_UNAVAILABLE["AORRTC"] = "with ompl 2.0.1 it reports zero-length paths when any solution is good enough"
# Planners that keep improving until the time is up; they stop at the first exact solution here unless asked.
_OPTIMIZING = {"RRTstar", "InformedRRTstar", "PRMstar", "BITstar", "FMT", "BFMT", "PRM"}
# Planners whose OMPL solve() starts a second thread that runs the (Python) validity checker under the roadmap's
# lock while the calling thread holds the GIL and waits for that lock: a deadlock. Their roadmaps are grown and
# queried in the calling thread instead (roboscript.planning.roadmap).
_ROADMAP_PLANNERS = {"PRM", "PRMstar"}


def planner_names() -> list[str]:
    """The selectable planners."""
    return list(_PLANNER_CLASSES)


def canonical_planner_name(name: str) -> str:
    name = _ALIASES.get(name, name)
    if name not in _PLANNER_CLASSES:
        raise UnknownPlannerError(name, planner_names(), _UNAVAILABLE)
    return name


@dataclass(frozen=True)
class JointPath:
    """A collision-free piecewise-linear path in joint space, from a planner or a Cartesian interpolation."""

    waypoints: np.ndarray  # (N, dof)
    planner: str = ""
    planning_time: float = 0.0  # seconds in the planner and simplifier
    validation_time: float = 0.0  # seconds of dense validation
    replans: int = 0  # times the path failed dense validation and was planned again with finer checks
    attempts: int = 1  # planner runs it took, each with twice the time of the one before (MotionPlanner.plan)

    @property
    def start(self) -> np.ndarray:
        return self.waypoints[0]

    @property
    def goal(self) -> np.ndarray:
        return self.waypoints[-1]

    def length(self) -> float:
        return float(np.sum(np.linalg.norm(np.diff(self.waypoints, axis=0), axis=1)))


def densify(waypoints: np.ndarray, lever: np.ndarray, step: float) -> np.ndarray:
    """Points along the polyline such that no point of the arm moves more than ``step`` metres between two."""
    out = [waypoints[0]]
    for a, b in itertools.pairwise(waypoints):
        motion = float(np.sum(np.abs(b - a) * lever))
        n = max(1, int(np.ceil(motion / step)))
        for k in range(1, n + 1):
            out.append(a + (b - a) * (k / n))
    return np.array(out)


TURN = 2 * np.pi


def whole_turn_equivalents(q: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> list[np.ndarray]:
    """``q`` first, then each configuration one joint's whole turn away from it within the limits: the same pose
    of the arm, reached by turning that joint the other way round."""
    out = [q]
    for j in range(len(q)):
        for turn in (-TURN, TURN):
            if lower[j] <= q[j] + turn <= upper[j]:
                other = q.copy()
                other[j] += turn
                out.append(other)
    return out


def whole_turns(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The whole turns per joint (multiples of 2 pi) nearest ``b - a``: add them to a path from ``a`` to continue
    it from ``b`` where ``b`` is ``a``'s pose turned whole turns."""
    return TURN * np.round((np.asarray(b, dtype=float) - np.asarray(a, dtype=float)) / TURN)


def same_pose(a: np.ndarray, b: np.ndarray, tolerance: float) -> bool:
    """Whether configurations ``a`` and ``b`` put every joint within ``tolerance`` radians of the same angle,
    whole turns aside."""
    return pose_distance(a, b) < tolerance


def pose_distance(a: np.ndarray, b: np.ndarray) -> float:
    """The largest joint angle between configurations ``a`` and ``b``, whole turns aside (radians)."""
    difference = np.asarray(b, dtype=float) - np.asarray(a, dtype=float)
    return float(np.max(np.abs(difference - whole_turns(np.zeros_like(difference), difference))))


def simplify_path(og, info, path) -> None:
    """Shortens an OMPL path in place with a fixed amount of work: vertices that can be skipped are, close ones
    merge, and corners are shortcut (OMPL's "rope" shortcut).

    OMPL's own ``simplifySolution`` adds rounds of B-spline smoothing until a time limit, and with a limit of a
    tenth of a second it ran out of time on most paths here: two thirds of all the planner's collision checks,
    a result that depended on how busy the machine was, for paths that took the arm no less time to follow (16
    trials of the eight paper tasks: the simulated time summed 306 s against 310 s with it, every trial a
    success both ways)."""
    simplifier = og.PathSimplifier(info)
    simplifier.reduceVertices(path)
    simplifier.collapseCloseVertices(path)
    simplifier.reduceVertices(path)
    simplifier.ropeShortcutPath(path)


class JointPlanner:
    """Plans collision-free joint paths in a :class:`PlanningScene` with a chosen OMPL planner."""

    def __init__(self, scene: PlanningScene, check_step: float = 0.08, validation_step: float | None = None):
        """``check_step``: joint-space distance (radians) between the planner's own motion checks; the dense
        validation afterwards makes the path safe, this only sets how often the planner must repair.
        ``validation_step``: metres any point of the arm may move between two checks of the final path (default:
        the scene's padding, which makes the validation exhaustive).
        """
        self.scene = scene
        self.check_step = check_step
        self.validation_step = scene.padding if validation_step is None else validation_step
        if self.validation_step <= 0:
            raise ValueError("validation_step must be > 0 metres (the scene's padding is 0: give one explicitly)")

    def check_state(self, q: np.ndarray, which: str) -> None:
        """Raises if ``q`` is out of limits or in collision, naming the joint or the bodies."""
        q = np.asarray(q, dtype=float)
        if q.shape != (self.scene.dof,):
            raise ValueError(f"the {which} configuration must have {self.scene.dof} joint values, got shape {q.shape}")
        lower, upper = self.scene.joint_lower, self.scene.joint_upper
        outside = np.flatnonzero((q < lower - 1e-6) | (q > upper + 1e-6))
        if outside.size:
            j = int(outside[0])
            raise PlanningError(
                f"the {which} configuration is outside the joint limits: joint {j + 1} is {q[j]:.3f} rad, "
                f"limits [{lower[j]:.3f}, {upper[j]:.3f}]"
            )
        if not self.scene.is_valid(q):
            raise StateInCollisionError(which, self.scene.collisions(q))

    def validate(self, waypoints: np.ndarray) -> None:
        """Dense validation; raises :class:`PathInCollisionError` at the first colliding point."""
        blocked = first_blocked(self.scene, waypoints, self.validation_step)
        if blocked is not None:
            raise PathInCollisionError(blocked.segment, len(waypoints) - 1, self.scene.collisions(blocked.q))

    @timed("planning")
    def plan(
        self,
        start: np.ndarray,
        goal: np.ndarray,
        planner: str = "RRTConnect",
        timeout: float = 2.0,
        simplify: bool = True,
        optimize: bool = False,
        constraint: Callable[[np.ndarray], bool] | None = None,
    ) -> JointPath:
        """A validated collision-free path from ``start`` to ``goal``, or to ``goal`` turned a whole turn about a
        joint that can turn more than once (see :func:`whole_turn_equivalents`; ``JointPath.goal`` says which).
        ``constraint``: a path constraint every configuration along the path must meet besides being free (as
        MoveIt's path constraints: keeping a held cup upright), checked as often as collisions are.

        Optimising planners stop at their first exact solution unless ``optimize`` is set (then they use the
        whole ``timeout``). Raises :class:`StateInCollisionError`, :class:`PlannerTimeoutError` or
        :class:`UnknownPlannerError`.
        """
        name = canonical_planner_name(planner)
        start, goal = np.asarray(start, dtype=float), np.asarray(goal, dtype=float)
        self.check_state(start, "start")
        self.check_state(goal, "goal")
        began = time.perf_counter()
        validation = 0.0
        check_step = self.check_step
        for attempt in range(3):
            # The planner's motion checks are coarse for speed; a path that fails the dense validation is planned
            # again with checks four times finer (rare: a graze between two coarse checks).
            waypoints = self._solve(name, start, goal, timeout, simplify, optimize, check_step, constraint)
            checked = time.perf_counter()
            blocked = first_blocked(self.scene, waypoints, self.validation_step)
            validation += time.perf_counter() - checked
            if blocked is None:
                total = time.perf_counter() - began
                return JointPath(waypoints, name, total - validation, validation, attempt)
            check_step /= 4
        raise PathInCollisionError(blocked.segment, len(waypoints) - 1, self.scene.collisions(blocked.q))

    def _solve(
        self,
        name: str,
        start: np.ndarray,
        goal: np.ndarray,
        timeout: float,
        simplify: bool,
        optimize: bool,
        check_step: float,
        constraint: Callable[[np.ndarray], bool] | None = None,
    ) -> np.ndarray:
        ob, og, _ = import_ompl()
        dof = self.scene.dof
        space = ob.RealVectorStateSpace(dof)
        bounds = ob.RealVectorBounds(dof)
        for j in range(dof):
            bounds.setLow(j, float(self.scene.joint_lower[j]))
            bounds.setHigh(j, float(self.scene.joint_upper[j]))
        space.setBounds(bounds)
        setup = og.SimpleSetup(space)
        is_free = self.scene.is_free  # OMPL samples within the joint bounds: no limit check needed
        buffer = np.empty(dof)
        indices = range(dof)

        def valid(state) -> bool:
            for j in indices:
                buffer[j] = state[j]
            return is_free(buffer) and (constraint is None or constraint(buffer))

        setup.setStateValidityChecker(valid)
        info = setup.getSpaceInformation()
        info.setStateValidityCheckingResolution(min(1.0, check_step / space.getMaximumExtent()))
        start_state = self._state(space, start)
        equivalents = whole_turn_equivalents(goal, self.scene.joint_lower, self.scene.joint_upper)
        if len(equivalents) == 1:
            # One goal state: OMPL's own single-goal set-up (RRTConnect draws its random numbers otherwise, and
            # the paths of an arm with no whole turns stay what they were).
            setup.setStartAndGoalStates(start_state, self._state(space, goal))
        else:
            setup.setStartState(start_state)
            # The goal itself first: RRTConnect grows its goal tree from the goals in order, adding the others as
            # it grows, so a goal that connects directly is still the one reached.
            goals = ob.GoalStates(info)
            for equivalent in equivalents:
                goals.addState(self._state(space, equivalent))
            setup.setGoal(goals)
        planner = getattr(og, _PLANNER_CLASSES[name])(info)
        if constraint is not None and hasattr(planner, "setRange"):
            # A tree grows by a step only where all of the step meets the constraint. OMPL's default step, a fifth
            # of the joint space's extent (six radians for a UR5e), almost never keeps a held mug upright: its
            # upright transfers ran out of 2, 4 and 8 s where steps of half a radian found them in 0.05-0.2 s.
            planner.setRange(CONSTRAINED_RANGE)
        setup.setPlanner(planner)
        if name in _OPTIMIZING and not optimize:
            # Any path is good enough: the optimising planners then stop at their first solution.
            objective = ob.PathLengthOptimizationObjective(info)
            objective.setCostThreshold(ob.Cost(float("inf")))
            setup.setOptimizationObjective(objective)
        if name in _ROADMAP_PLANNERS:
            path = self._roadmap_solve(name, planner, setup, space, start, equivalents, timeout, optimize)
        else:
            setup.solve(timeout)
            if not setup.haveExactSolutionPath():
                raise PlannerTimeoutError(name, timeout)
            path = setup.getSolutionPath()
        if simplify:
            simplify_path(og, info, path)
        return np.array([[path.getState(i)[j] for j in range(dof)] for i in range(path.getStateCount())])

    def _roadmap_solve(
        self,
        name: str,
        planner,
        setup,
        space,
        start: np.ndarray,
        goals: list[np.ndarray],
        timeout: float,
        optimize: bool,
    ):
        """PRM or PRM* without OMPL's solve() (see ``_ROADMAP_PLANNERS``): an OMPL path from ``start`` to the first
        of ``goals`` reached on the planner's roadmap, grown in this thread."""
        ob, og, _ = import_ompl()
        setup.setup()  # hands the planner the problem and sets it up, as solve() would
        # Asked to optimise (no objective of ours), OMPL's PRM gives its default objective an infinite cost threshold
        # and stops at its first path all the same; PRM*'s threshold is 0, so it improves until the time is up.
        improve = optimize and name == "PRMstar"
        info = setup.getSpaceInformation()
        star = name == "PRMstar"
        waypoints = roadmap_path(ob, planner, space, info, start, goals, timeout, star=star, improve=improve)
        if waypoints is None:
            raise PlannerTimeoutError(name, timeout)
        path = og.PathGeometric(info)
        for q in waypoints:
            path.append(self._state(space, q))
        return path

    @staticmethod
    def _state(space, q: np.ndarray):
        """An OMPL state of ``space`` at ``q``."""
        state = space.allocState()
        for j in range(len(q)):
            state[j] = float(q[j])
        return state
