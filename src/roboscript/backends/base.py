"""The robot backend interface: what the tool API and the planners may ask of a robot, simulated or real.

A backend speaks in plain data (numpy arrays, :class:`Transform`, :class:`JointTrajectory`, :class:`CameraFrame`),
so a ROS backend can implement it with joint states, a ``FollowJointTrajectory`` action, gripper commands, camera
topics and TF, and nothing above this layer needs to know which one it talks to.

Ground truth exists only in simulation: :attr:`Backend.ground_truth` is ``None`` on a real robot.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from roboscript.errors import RoboScriptError
from roboscript.geometry import Transform
from roboscript.robot_io import CameraFrame, ExecutionReport, GripperReport
from roboscript.robots import RobotDescription
from roboscript.trajectory import JointTrajectory

if TYPE_CHECKING:  # ground truth is the simulation's; the interface only names its type
    from roboscript.sim.ground_truth import GroundTruth

ClockListener = Callable[[float], None]


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
    def joint_states(self) -> dict[str, float]:
        """Every joint of the arm and the gripper by its name in the robot's model (unprefixed), as the encoders
        read it: radians or metres."""

    @abstractmethod
    def base_pose(self) -> Transform:
        """World pose of the robot's base frame, where its model is mounted."""

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
    def capture(self, camera: str, color: bool = True, segmentation: bool = True) -> CameraFrame:
        """One RGB-D frame with calibration; segmentation only where the backend can provide it.

        ``color=False`` says the colour image will not be looked at: a backend that must make it (a simulator
        renders it, at more than half a capture's cost) may then leave it out (``rgb`` None); others send it anyway.
        ``segmentation=False`` says the same of the segmentation image (a simulator then neither reads nor labels
        it).
        """

    def segmentation_labels(self) -> dict[int, str]:
        """What the segmentation images of :meth:`capture` label: index -> name (``robot`` for the robot's own
        pixels); empty where frames carry no segmentation."""
        return {}

    def workspace_box(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The box (world frame: lower and upper corner, metres) that every link of the arm must stay inside, where
        the backend refuses motions that leave one (a real arm's safety limits); None where there is none. Planners
        keep their paths inside it, so that a motion they find is one the backend will send."""
        return None

    # --- for people watching ---

    def render(self, camera: str, width: int, height: int) -> np.ndarray:
        """An RGB image (height, width, 3) of what ``camera`` sees, for videos; by default its captured frame,
        resized by nearest neighbour."""
        rgb = self.capture(camera).rgb
        rows = np.arange(height) * rgb.shape[0] // height
        cols = np.arange(width) * rgb.shape[1] // width
        return np.ascontiguousarray(rgb[rows][:, cols])

    def add_clock_listener(self, listener: ClockListener) -> None:
        """Calls ``listener(time)`` as the backend's clock advances: every physics step in simulation, every joint
        state received on a robot."""
        self.__dict__.setdefault("_clock_listeners", []).append(listener)

    def remove_clock_listener(self, listener: ClockListener) -> None:
        listeners = self.__dict__.get("_clock_listeners", [])
        if listener in listeners:
            listeners.remove(listener)

    def _clock_advanced(self, time: float) -> None:
        """Implementations call this as their clock advances."""
        for listener in list(self.__dict__.get("_clock_listeners", ())):
            listener(time)

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
