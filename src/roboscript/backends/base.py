"""The robot backend interface: what the tool API and the planners may ask of a robot, simulated or real.

A backend speaks in plain data (numpy arrays, :class:`Transform`, :class:`JointTrajectory`, :class:`CameraFrame`),
so a ROS backend can implement it with joint states, a ``FollowJointTrajectory`` action, gripper commands, camera
topics and TF, and nothing above this layer needs to know which one it talks to.

Ground truth exists only in simulation: :attr:`Backend.ground_truth` is ``None`` on a real robot.
"""

from __future__ import annotations

from abc import ABC, abstractmethod

import numpy as np

from roboscript.errors import RoboScriptError
from roboscript.geometry import Transform
from roboscript.robots import RobotDescription
from roboscript.sim.cameras import CameraFrame
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.simulator import ExecutionReport, GripperReport
from roboscript.sim.trajectory import JointTrajectory


class BackendError(RoboScriptError, RuntimeError):
    """A backend could not do what was asked (the message says what and why)."""


class Backend(ABC):
    """A robot arm with a parallel gripper and fixed RGB-D cameras."""

    @property
    @abstractmethod
    def robot(self) -> RobotDescription:
        """The arm and gripper this backend drives."""

    # --- state ---

    @abstractmethod
    def joint_positions(self) -> np.ndarray:
        """Arm joint positions, radians, in the description's joint order."""

    @abstractmethod
    def tcp_pose(self) -> Transform:
        """World pose of the tool centre point (z: approach direction, y: finger closing direction)."""

    @abstractmethod
    def gripper_width(self) -> float:
        """Opening between the fingers, metres."""

    @abstractmethod
    def time(self) -> float:
        """Seconds on the backend's clock (simulated time in simulation)."""

    # --- motion ---

    @abstractmethod
    def execute_trajectory(self, trajectory: JointTrajectory) -> ExecutionReport:
        """Runs a joint trajectory that starts at the current configuration; returns when it has finished."""

    @abstractmethod
    def set_gripper(self, closed: float) -> GripperReport:
        """Commands the gripper (0 open .. 1 closed); returns when the fingers have stopped."""

    def open_gripper(self) -> GripperReport:
        return self.set_gripper(0.0)

    def close_gripper(self) -> GripperReport:
        return self.set_gripper(1.0)

    @abstractmethod
    def wait(self, seconds: float) -> None:
        """Lets time pass with the robot holding still."""

    # --- sensing ---

    @abstractmethod
    def camera_names(self) -> list[str]:
        """Names of the RGB-D cameras, in rig order."""

    @abstractmethod
    def capture(self, camera: str) -> CameraFrame:
        """One RGB-D frame with calibration; segmentation only where the backend can provide it."""

    # --- simulation only ---

    @property
    def ground_truth(self) -> GroundTruth | None:
        """True world state in simulation; ``None`` on a real robot."""
        return None

    def close(self) -> None:  # noqa: B027 - optional hook, most backends hold nothing to release
        """Releases renderers, connections and processes."""

    def __enter__(self) -> Backend:
        return self

    def __exit__(self, *exc) -> None:
        self.close()
