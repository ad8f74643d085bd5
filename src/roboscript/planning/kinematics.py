"""Arm kinematics on a robot-only MuJoCo model: forward kinematics of the TCP and inverse kinematics with mink.

The model holds just the robot at its mount, so IK works on the arm's few joints rather than on every object of
the world. Collision-aware choice among solutions is :mod:`roboscript.planning.ik`'s job.
"""

from __future__ import annotations

from dataclasses import dataclass

import mink
import numpy as np

from roboscript.geometry import Transform, quat_to_matrix
from roboscript.robots import ROBOT_PREFIX, RobotDescription
from roboscript.robots.mujoco_model import RobotModel


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
            self.tcp_site_name, "site", position_cost=1.0, orientation_cost=0.5, lm_damping=1e-3
        )
        self._limits = [mink.ConfigurationLimit(self.model, gain=0.95)]

    @property
    def dof(self) -> int:
        return len(self._qpos)

    def fk(self, q: np.ndarray) -> Transform:
        """The TCP pose at arm configuration ``q``."""
        return self._robot.tcp(q)

    def solve(
        self,
        target: Transform,
        seed: np.ndarray,
        max_iterations: int = 60,
        position_tolerance: float = 2e-4,
        angle_tolerance: float = 2e-3,
    ) -> IKResult:
        """Runs IK from ``seed`` towards ``target``, within joint limits; returns where it ended."""
        qpos = self.model.qpos0.copy()
        qpos[self._qpos] = np.clip(seed, self.lower, self.upper)
        self._configuration.update(qpos)
        self._task.set_target(
            mink.SE3.from_rotation_and_translation(
                mink.SO3.from_matrix(quat_to_matrix(target.quaternion)), target.position
            )
        )
        dt = 1.0
        position_error = angle_error = np.inf
        for _ in range(max_iterations):
            error = self._task.compute_error(self._configuration)
            position_error, angle_error = float(np.linalg.norm(error[:3])), float(np.linalg.norm(error[3:]))
            if position_error < position_tolerance and angle_error < angle_tolerance:
                break
            velocity = mink.solve_ik(
                self._configuration, [self._task], dt, solver="daqp", damping=1e-4, limits=self._limits
            )
            self._configuration.integrate_inplace(velocity, dt)
        q = self._configuration.q[self._qpos].copy()
        converged = position_error < position_tolerance and angle_error < angle_tolerance
        return IKResult(np.clip(q, self.lower, self.upper), position_error, angle_error, converged)
