"""The driver interface: the transport to a robot, whatever carries it (ROS 1 here; ROS 2 or a vendor SDK the same
way, one module each).

A driver speaks in the robot's own joint names and in plain data; it does no planning and no safety checks, which
:class:`~roboscript.backends.driven.DriverBackend` does once for every transport.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from roboscript.errors import FailureError
from roboscript.robot_io import CameraFrame
from roboscript.trajectory import JointTrajectory


class DriverError(FailureError, RuntimeError):
    """The robot could not be reached or refused a command; the message says which part and why."""


@dataclass(frozen=True)
class JointStateReading:
    """One joint-state message: positions by the driver's joint names, its stamp on the robot's clock, and when it
    arrived here (seconds of ``time.monotonic``)."""

    positions: dict[str, float]
    stamp: float
    received: float


@dataclass(frozen=True)
class GoalStatus:
    """Where a sent trajectory stands: ``active``, ``succeeded``, ``aborted``, ``rejected``, ``cancelled`` or
    ``lost`` (the server went away); ``detail`` is what the server said."""

    state: str
    detail: str = ""

    @property
    def done(self) -> bool:
        return self.state != "active"


@dataclass(frozen=True)
class TrackingSample:
    """The controller's own account of how it tracks: set-point and measured positions, in the order sent."""

    desired: np.ndarray
    actual: np.ndarray


class TrajectoryGoal(ABC):
    """A trajectory sent to the robot's controller."""

    def tracking(self) -> TrackingSample | None:
        """The controller's latest feedback, None before any (or from a controller that gives none)."""
        return None

    @abstractmethod
    def status(self) -> GoalStatus:
        """Where the goal stands now (does not wait)."""

    @abstractmethod
    def cancel(self) -> None:
        """Asks the controller to stop this goal (the arm holds where it is)."""


@dataclass(frozen=True)
class GripperResult:
    """The gripper after a command: the driver's position reading, and whether the fingers stalled on something
    (None where the driver does not say: the backend then tells it from the opening)."""

    position: float
    stalled: bool | None
    reached: bool


class CameraSource(ABC):
    """Cameras read apart from the arm's transport (RealSense cameras through librealsense, say)."""

    @abstractmethod
    def names(self) -> list[str]:
        """The cameras this source reads."""

    @abstractmethod
    def frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        """A complete RGB-D frame of ``camera`` captured at ``not_before`` (seconds of ``time.monotonic``) or later,
        with its calibration and its pose in the world frame; :class:`DriverError` after ``timeout`` seconds."""

    def close(self) -> None:  # noqa: B027 - optional hook
        """Stops the cameras."""


class Driver(ABC):
    """A robot arm with a gripper and cameras, reached over some transport."""

    @abstractmethod
    def joint_state(self) -> JointStateReading | None:
        """The latest joint state received, None before the first."""

    @abstractmethod
    def now(self) -> float:
        """Seconds on the robot's clock (the clock joint states are stamped with)."""

    @abstractmethod
    def send_trajectory(self, joint_names: list[str], trajectory: JointTrajectory) -> TrajectoryGoal:
        """Sends ``trajectory`` (columns in ``joint_names`` order) to the arm's controller; raises
        :class:`DriverError` if no controller answers within the driver's timeout."""

    @abstractmethod
    def command_gripper(self, position: float, closing: bool, timeout: float) -> GripperResult:
        """Moves the gripper to ``position`` (the driver's unit), closing on what is between the fingers when
        ``closing``; waits up to ``timeout`` seconds."""

    @abstractmethod
    def camera_names(self) -> list[str]:
        """The cameras the driver reads."""

    @abstractmethod
    def camera_frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        """A complete RGB-D frame of ``camera`` taken at ``not_before`` (robot clock) or later, with its calibration
        and its pose in the world frame."""

    def segmentation_labels(self) -> dict[int, str]:
        """What the segmentation images' labels stand for; empty without segmentation."""
        return {}

    def close(self) -> None:  # noqa: B027 - optional hook
        """Releases connections."""
