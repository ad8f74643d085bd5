"""Arm kinematics on a robot-only MuJoCo model: forward kinematics of the TCP and inverse kinematics, in closed
form for arms of the UR family (:mod:`roboscript.planning.closed_form_ik`), else iterative (mink's frame task, its
quadratic program solved directly).

The model holds just the robot at its mount, so IK works on the arm's few joints rather than on every object of
the world. Collision-aware choice among solutions is :mod:`roboscript.planning.ik`'s job.
"""

from __future__ import annotations

from dataclasses import dataclass

import mink
import mujoco
import numpy as np

from roboscript.geometry import Transform, quat_to_matrix, rotation_angle_between
from roboscript.phases import timed
from roboscript.planning.box_qp import solve_box_qp
from roboscript.planning.closed_form_ik import ClosedFormIK, NotClosedFormError
from roboscript.robots import ROBOT_PREFIX, RobotDescription
from roboscript.robots.mujoco_model import RobotModel

POSITION_COST, ORIENTATION_COST = 1.0, 0.5  # an orientation error of 1 rad weighs as 0.5 m of position error
LM_DAMPING = 1e-3  # Levenberg-Marquardt damping, scaled by the squared weighted error
DAMPING = 1e-4  # constant damping: steps stay bounded near singularities
LIMIT_GAIN = 0.95  # a step may cover this share of the way to a joint's limit
# A run whose least error has not fallen by a tenth in 10 iterations is given up, and the next seed tried: seeds
# that never converge took most of IK's time. Over seven reference trials of both arms (9,700 runs) a window of 10
# iterations instead of 20 took 35-40% fewer iterations and gave up 0-1.4% of the runs that would have converged,
# slowly, later (they plateau far from the target first: no error floor spares them).
STALL_WINDOW, STALL_RATIO = 10, 0.9


@dataclass(frozen=True)
class IKResult:
    """Where an IK run ended: the configuration and its position and angle error to the target."""

    q: np.ndarray
    position_error: float
    angle_error: float
    converged: bool


class ArmKinematics:
    """TCP forward and inverse kinematics for one robot at one mount pose."""

    def __init__(self, description: RobotDescription, mount: Transform):
        robot = RobotModel(description, mount)
        self.description = description
        self.mount = mount
        self.model, self.data = robot.model, robot.data
        self._robot = robot
        q = RobotDescription.qualified
        self._qpos = np.array([self.model.joint(q(j)).qposadr[0] for j in description.arm_joints])
        self.lower, self.upper = robot.joint_lower, robot.joint_upper
        self.tcp_site_name = ROBOT_PREFIX + description.tcp_site
        self._configuration = mink.Configuration(self.model)
        self._task = mink.FrameTask(
            self.tcp_site_name, "site", position_cost=POSITION_COST, orientation_cost=ORIENTATION_COST
        )
        self._cost = np.array([POSITION_COST] * 3 + [ORIENTATION_COST] * 3)
        self._arm_dofs = np.array([self.model.joint(q(j)).dofadr[0] for j in description.arm_joints])
        self.closed_form, self.closed_form_absent = self._closed_form()

    def _closed_form(self) -> tuple[ClosedFormIK | None, str]:
        """The arm's closed-form IK, read off its joint axes at the zero configuration; or None and why not."""
        self.data.qpos[:] = self.model.qpos0
        self.data.qpos[self._qpos] = 0.0
        mujoco.mj_kinematics(self.model, self.data)
        joints = [self.model.joint(RobotDescription.qualified(j)).id for j in self.description.arm_joints]
        axes, points = self.data.xaxis[joints].copy(), self.data.xanchor[joints].copy()
        try:
            return ClosedFormIK.from_zero_configuration(axes, points, self.fk(np.zeros(self.dof))), ""
        except NotClosedFormError as exc:
            return None, str(exc)

    @property
    def dof(self) -> int:
        return len(self._qpos)

    def fk(self, q: np.ndarray) -> Transform:
        """The TCP pose at arm configuration ``q``."""
        return self._robot.tcp(q)

    @timed("ik")
    def solve(
        self,
        target: Transform,
        seed: np.ndarray,
        max_iterations: int = 60,
        position_tolerance: float = 2e-4,
        angle_tolerance: float = 2e-3,
    ) -> IKResult:
        """Runs iterative IK from ``seed`` towards ``target``, within joint limits; returns where it ended. (From a
        seed near the answer, as along a Cartesian line, this is quicker than :meth:`closed_form_solutions`.)"""
        qpos = self.model.qpos0.copy()
        qpos[self._qpos] = np.clip(seed, self.lower, self.upper)
        self._configuration.update(qpos)
        self._task.set_target(
            mink.SE3.from_rotation_and_translation(
                mink.SO3.from_matrix(quat_to_matrix(target.quaternion)), target.position
            )
        )
        position_error = angle_error = np.inf
        best: list[float] = []  # the least weighted error so far, after each iteration
        for iteration in range(max_iterations):
            error = self._task.compute_error(self._configuration)
            position_error, angle_error = float(np.linalg.norm(error[:3])), float(np.linalg.norm(error[3:]))
            if position_error < position_tolerance and angle_error < angle_tolerance:
                break
            weighted = POSITION_COST * position_error + ORIENTATION_COST * angle_error
            best.append(min(weighted, best[-1]) if best else weighted)
            if iteration >= STALL_WINDOW and best[-1] > STALL_RATIO * best[-1 - STALL_WINDOW]:
                break  # stalled: at a limit or in a local minimum short of the target
            self._configuration.integrate_inplace(self._step(error), 1.0)
        q = self._configuration.q[self._qpos].copy()
        converged = position_error < position_tolerance and angle_error < angle_tolerance
        return IKResult(np.clip(q, self.lower, self.upper), position_error, angle_error, converged)

    @timed("ik")
    def closed_form_solutions(
        self,
        target: Transform,
        reference: np.ndarray,
        position_tolerance: float = 2e-4,
        angle_tolerance: float = 2e-3,
    ) -> list[IKResult]:
        """Every solution of the closed form within the joint limits, each joint turned by whole turns towards
        ``reference`` where its range allows, and each checked by forward kinematics (a pose at the very edge of
        reach may be missed by a hair: the iterative solver then decides). Raises ValueError for an arm without
        one (see :attr:`closed_form_absent`)."""
        if self.closed_form is None:
            raise ValueError(f"the {self.description.name} has no closed-form IK: {self.closed_form_absent}")
        reference = np.asarray(reference, dtype=float)
        out = []
        for q in self.closed_form.solutions(target, reference):
            q = nearest_equivalent(q, reference, self.lower, self.upper)
            if np.any(q < self.lower) or np.any(q > self.upper):
                continue
            reached = self.fk(q)
            position_error = float(np.linalg.norm(reached.position - target.position))
            angle_error = rotation_angle_between(reached.quaternion, target.quaternion)
            if position_error < position_tolerance and angle_error < angle_tolerance:
                out.append(IKResult(q, position_error, angle_error, True))
        return out

    def _step(self, error: np.ndarray) -> np.ndarray:
        """One damped least-squares step towards the target, each joint kept within a share of the way to its
        limits: the quadratic program mink poses (a frame task with Levenberg-Marquardt damping, a configuration
        limit), solved directly (see :mod:`roboscript.planning.box_qp`)."""
        # Only the arm's joints move the TCP: the others' columns are zero, and so would be their steps.
        jacobian = self._task.compute_jacobian(self._configuration)[:, self._arm_dofs]
        weighted_error = self._cost * -error
        weighted = self._cost[:, None] * jacobian
        hessian = weighted.T @ weighted
        hessian.flat[:: hessian.shape[0] + 1] += DAMPING + LM_DAMPING * float(weighted_error @ weighted_error)
        linear = -(weighted_error @ weighted)
        q = self._configuration.q[self._qpos]
        # A joint a hair outside its range (clipping leaves it on the bound) must not make zero infeasible.
        lower = np.minimum(LIMIT_GAIN * (self.lower - q), 0.0)
        upper = np.maximum(LIMIT_GAIN * (self.upper - q), 0.0)
        step = np.zeros(self.model.nv)
        step[self._arm_dofs] = solve_box_qp(hessian, linear, lower, upper)
        return step


def nearest_equivalent(q: np.ndarray, reference: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """Moves joints by whole turns towards ``reference`` where the limits allow (wrist joints with +-2 pi range)."""
    q = q.copy()
    for j in range(len(q)):
        for shift in (-2 * np.pi, 2 * np.pi):
            candidate = q[j] + shift
            if lower[j] <= candidate <= upper[j] and abs(candidate - reference[j]) < abs(q[j] - reference[j]):
                q[j] = candidate
    return q
