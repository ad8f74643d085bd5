"""Transfers of a held object: lifted straight off what it rests on, carried clear of everything, lowered straight.

A planner given the held object's ordinary padding finds paths that skim the table or a container's rim by a few
millimetres; the arm tracks its trajectory to within a few millimetres too, and a held box that grazes the table
is knocked out of the fingers. A transfer keeps the held object :data:`HELD_CLEARANCE` clear of everything in
the planned part, and reaches that clearance, at both ends, along straight lines up from the start and down to the
goal, as the retreat and approach of a pick-and-place pipeline do.

The carried part also keeps the held object upright, as a MoveIt path constraint would: it tilts no more than
:data:`TILT_ALLOWANCE` beyond the tilt it must have at the goal. A joint-space path between two IK branches (the
arm turned round) otherwise tips the hand over on the way, and a banana held from above slides out of the fingers.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from roboscript.geometry import Transform
from roboscript.planning.cartesian import cartesian_path
from roboscript.planning.errors import PlanningError
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.planner import JointPath, JointPlanner, whole_turns
from roboscript.planning.scene import PlanningScene
from roboscript.planning.scene_variants import held_clearance

HELD_CLEARANCE = 0.02  # metres a held object keeps from everything while it is carried
MAX_LIFT = 0.15  # metres the lines at either end may rise to reach that clearance
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


def plan_transfer(
    planner: JointPlanner,
    kinematics: ArmKinematics,
    start: np.ndarray,
    goal: np.ndarray,
    name: str,
    timeout: float,
) -> JointPath:
    """Lift from ``start``, a planned path that keeps the held object clear and upright, lowering into ``goal``; raises
    :class:`PlanningError` (or the planner's errors) where that cannot be done."""
    scene = planner.scene
    lift = to_clearance(kinematics, scene, start)
    lower = to_clearance(kinematics, scene, goal)[::-1]
    constraint = upright(kinematics, lift[-1], lower[0])
    with held_clearance(scene, HELD_CLEARANCE):
        carried = planner.plan(lift[-1], lower[0], name, timeout, constraint=constraint)
    # The carried part may end at the lowering line's start turned a whole turn about a joint.
    lower = lower + whole_turns(lower[0], carried.goal)
    if not (scene.within_limits(lower.min(axis=0)) and scene.within_limits(lower.max(axis=0))):
        raise PlanningError("the lowering line, turned as the carried path arrives, leaves the joint limits")
    waypoints = np.vstack([lift[:-1], carried.waypoints, lower[1:]])
    return JointPath(waypoints, carried.planner, carried.planning_time, carried.validation_time, carried.replans)
