"""Transfers of a held object: lifted straight off what it rests on, carried clear of everything, lowered straight.

A planner given the held object's ordinary padding finds paths that skim the table or a container's rim by a few
millimetres; the arm tracks its trajectory to within a few millimetres too, and a held box that grazes the table
is knocked out of the fingers. A transfer keeps the held object :data:`HELD_CLEARANCE` clear of everything in
the planned part, and reaches that clearance, at both ends, along straight lines up from the start and down to the
goal, as the retreat and approach of a pick-and-place pipeline do.

The carried part also keeps the held object upright, as a MoveIt path constraint would: it tilts no more than
:data:`TILT_ALLOWANCE` beyond the tilt it must have at the goal. A joint-space path between two IK branches (the
arm turned round) otherwise tips the hand over on the way, and a banana held from above slides out of the fingers.

The carried part is found without a planner where it can be (:func:`carry_over`): the straight joint line between
its ends, else up from both ends to a common height, across, and down, as a pick-and-place pipeline's cruise
height does. A planner under the upright constraint took 1-2 s for a carry into a basket whose straight line dipped
into its rim; the way over it takes a few dozen IK steps.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

import numpy as np

from roboscript.geometry import Transform
from roboscript.planning.cartesian import cartesian_path
from roboscript.planning.errors import PlanningError
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.path_checks import first_blocked
from roboscript.planning.planner import JointPath, JointPlanner, whole_turns
from roboscript.planning.scene import PlanningScene
from roboscript.planning.scene_variants import held_clearance

HELD_CLEARANCE = 0.02  # metres a held object keeps from everything while it is carried
MAX_LIFT = 0.15  # metres the lines at either end may rise to reach that clearance
CRUISE_RISES = (0.05, 0.1, 0.2)  # metres above the higher end of a carry that a carry over the top tries, in turn
UPRIGHT_CHECK_STEP = 0.02  # radians any joint may turn between two checks of the upright constraint on a line
UP = np.array([0.0, 0.0, 1.0])
TILT_ALLOWANCE = math.radians(25)  # how far past its tilt at the goal a held object may tilt while carried


def upright(kinematics: ArmKinematics, start: np.ndarray, goal: np.ndarray) -> Callable[[np.ndarray], bool]:
    """A path constraint: the held object's upward direction at ``start`` (the world's up, in the hand's frame)
    tilts from the world's up by no more than its tilt at ``goal`` plus :data:`TILT_ALLOWANCE`."""
    held_up = kinematics.fk(start).rotation.T @ UP
    limit = math.cos(min(math.pi, held_tilt(kinematics, goal, held_up) + TILT_ALLOWANCE))

    def keeps_upright(q: np.ndarray) -> bool:
        return float((kinematics.fk(q).rotation @ held_up)[2]) >= limit

    return keeps_upright


def held_tilt(kinematics: ArmKinematics, q: np.ndarray, held_up: np.ndarray) -> float:
    """How far (radians) the held object's upward direction ``held_up`` (in the hand's frame) tilts from the
    world's up with the arm at ``q``."""
    return math.acos(float(np.clip((kinematics.fk(q).rotation @ held_up)[2], -1.0, 1.0)))


def to_clearance(kinematics: ArmKinematics, scene: PlanningScene, q: np.ndarray) -> np.ndarray:
    """Joint waypoints of the straight line up from ``q`` to where what the gripper holds is clear by
    :data:`HELD_CLEARANCE` (just ``q`` if it is already). Raises :class:`PlanningError` if the line is blocked
    before that."""
    with held_clearance(scene, HELD_CLEARANCE):
        if scene.is_valid(q):
            return np.array([q])
    pose = kinematics.fk(q)
    line = cartesian_path(kinematics, scene, q, [Transform(pose.position + MAX_LIFT * UP, pose.quaternion)])
    with held_clearance(scene, HELD_CLEARANCE):
        for k, waypoint in enumerate(line.waypoints):
            if scene.is_valid(waypoint):
                return line.waypoints[: k + 1]
    raise PlanningError(
        f"the held object does not come {HELD_CLEARANCE * 100:.0f} cm clear of its surroundings within "
        f"{MAX_LIFT * 100:.0f} cm straight up ({line.reason or 'still too close'})"
    )


def carry_over(
    kinematics: ArmKinematics,
    scene: PlanningScene,
    start: np.ndarray,
    goal: np.ndarray,
    constraint: Callable[[np.ndarray], bool],
    step: float,
) -> np.ndarray | None:
    """Joint waypoints of a carry from ``start`` to ``goal`` that needs no planner, or None where there is none:
    the straight joint line between them, else straight up from both to a common height (each of
    :data:`CRUISE_RISES` above the higher of the two, in turn), the straight joint line across, and straight down.
    The lines across keep what the gripper holds :data:`HELD_CLEARANCE` clear; the lines up and down keep the
    scene's padding, as the lines that reach the clearance do (a basket's rim may lean in over where the lowering
    line first comes clear of its walls). Every line meets ``constraint`` and is checked as densely as a planner's
    path is validated (no point of the arm moves more than ``step`` metres between two checks)."""
    if _line_clear(scene, constraint, start, goal, step):
        return np.array([start, goal])
    top = max(float(kinematics.fk(start).position[2]), float(kinematics.fk(goal).position[2]))
    up = _line_up(kinematics, scene, start, top + CRUISE_RISES[-1])
    down = _line_up(kinematics, scene, goal, top + CRUISE_RISES[-1])
    up_heights, down_heights = _tcp_heights(kinematics, up), _tcp_heights(kinematics, down)
    for rise in CRUISE_RISES:
        a, b = _first_at(up_heights, top + rise), _first_at(down_heights, top + rise)
        if a is None or b is None:
            return None  # a line up is cut short below this height
        across = _across(kinematics, scene, constraint, up[a], down[b], step)
        if across is not None:
            return np.vstack([up[:a], across, down[b - 1 :: -1] if b else down[:0]])
    return None


def _across(
    kinematics: ArmKinematics,
    scene: PlanningScene,
    constraint: Callable[[np.ndarray], bool],
    a: np.ndarray,
    b: np.ndarray,
    step: float,
) -> np.ndarray | None:
    """Joint waypoints from ``a`` to ``b`` at a carry's cruise height, or None: the straight joint line, else the
    TCP's straight line (a joint line that swings the arm round its base can sag by several centimetres on the
    way), each clear and meeting ``constraint``."""
    if _line_clear(scene, constraint, a, b, step):
        return np.array([a, b])
    with held_clearance(scene, HELD_CLEARANCE):
        line = cartesian_path(kinematics, scene, a, [kinematics.fk(b)])
    if line.fraction < 1.0 or not all(constraint(q) for q in line.waypoints):
        return None
    end = line.waypoints[-1]
    if np.allclose(end, b, atol=1e-6):
        return line.waypoints
    # The line may end on another IK branch than ``b``'s: it must be one the arm turns to in a straight joint line.
    return np.vstack([line.waypoints, b[None]]) if _line_clear(scene, constraint, end, b, step) else None


def _line_up(kinematics: ArmKinematics, scene: PlanningScene, q: np.ndarray, height: float) -> np.ndarray:
    """Joint waypoints of the TCP's straight line up from ``q`` towards ``height``, its orientation kept, as far
    as it goes."""
    pose = kinematics.fk(q)
    rise = height - float(pose.position[2])
    return cartesian_path(kinematics, scene, q, [Transform(pose.position + rise * UP, pose.quaternion)]).waypoints


def _tcp_heights(kinematics: ArmKinematics, waypoints: np.ndarray) -> np.ndarray:
    """The TCP's height at each of the joint ``waypoints``."""
    return np.array([kinematics.fk(q).position[2] for q in waypoints], dtype=float)


def _first_at(heights: np.ndarray, height: float) -> int | None:
    """The index of the first of ``heights`` at ``height`` or above (within a millimetre), or None."""
    reached = np.flatnonzero(heights >= height - 1e-3)
    return int(reached[0]) if reached.size else None


def _line_clear(
    scene: PlanningScene, constraint: Callable[[np.ndarray], bool], a: np.ndarray, b: np.ndarray, step: float
) -> bool:
    """Whether the straight joint line from ``a`` to ``b`` is free with what the gripper holds
    :data:`HELD_CLEARANCE` clear, and meets ``constraint`` all along."""
    turns = int(np.ceil(float(np.max(np.abs(b - a))) / UPRIGHT_CHECK_STEP))
    if not all(constraint(a + (b - a) * u) for u in np.linspace(0.0, 1.0, turns + 1)):
        return False
    with held_clearance(scene, HELD_CLEARANCE):
        return first_blocked(scene, np.array([a, b]), step) is None


def plan_transfer(
    planner: JointPlanner,
    kinematics: ArmKinematics,
    start: np.ndarray,
    goal: np.ndarray,
    name: str,
    timeout: float,
) -> JointPath:
    """Lift from ``start``, a carry that keeps the held object clear and upright (:func:`carry_over`, else
    planned), lowering into ``goal``; raises :class:`PlanningError` (or the planner's errors) where that cannot be
    done."""
    scene = planner.scene
    lift = to_clearance(kinematics, scene, start)
    lower = to_clearance(kinematics, scene, goal)[::-1]
    constraint = upright(kinematics, lift[-1], lower[0])
    began = time.perf_counter()
    over = carry_over(kinematics, scene, lift[-1], lower[0], constraint, planner.validation_step)
    if over is not None:
        carried = JointPath(over, "straight lines", time.perf_counter() - began)
    else:
        with held_clearance(scene, HELD_CLEARANCE):
            carried = planner.plan(lift[-1], lower[0], name, timeout, constraint=constraint)
    # The carried part may end at the lowering line's start turned a whole turn about a joint.
    lower = lower + whole_turns(lower[0], carried.goal)
    if not (scene.within_limits(lower.min(axis=0)) and scene.within_limits(lower.max(axis=0))):
        raise PlanningError("the lowering line, turned as the carried path arrives, leaves the joint limits")
    waypoints = np.vstack([lift[:-1], carried.waypoints, lower[1:]])
    return JointPath(waypoints, carried.planner, carried.planning_time, carried.validation_time, carried.replans)
