"""A backend that reports what it is told: every trajectory and gripper command, and where the arm was after each,
to whoever listens (a run's log, a dry run's plan). Everything else, the interface and what a simulator adds to it,
is the inner backend's."""

from __future__ import annotations

import contextlib
from collections.abc import Callable

import numpy as np

from roboscript.backends.base import Backend, ClockListener
from roboscript.geometry import Transform
from roboscript.robot_io import CameraFrame, ExecutionReport, GripperReport
from roboscript.robots import RobotDescription
from roboscript.trajectory import JointTrajectory

Entry = dict  # {"kind": "trajectory" | "gripper" | "state", "start_time": backend clock, ...}: JSON-ready


class LoggedBackend(Backend):
    """``inner``, with each command it is sent, and the arm's joint positions before the first and after each,
    passed to ``listener`` as JSON-ready entries (the commands also kept in :attr:`commands`). A trajectory is
    reported as the inner backend sends it: after its own checks (a real arm's speed scale), and as ``refused``, not
    sent, where they refuse it. A command that raised is followed by an ``error`` entry."""

    def __init__(self, inner: Backend, listener: Callable[[Entry], None] | None = None):
        self.inner = inner
        self._listener = listener
        self.commands: list[Entry] = []
        self._report(self._state())

    def _report(self, entry: Entry) -> None:
        if entry["kind"] in ("trajectory", "gripper"):
            self.commands.append(entry)
        if self._listener is not None:
            self._listener(entry)

    def _state(self) -> Entry:
        return {
            "kind": "state",
            "time": self.inner.time(),
            "joint_names": list(self.inner.robot.arm_joints),
            "positions": self.inner.joint_positions().tolist(),
            "gripper_width": float(self.inner.gripper_width()),
        }

    def _sent(self, entry: Entry, send: Callable[[], object]):
        self._report(entry)
        try:
            return send()
        except BaseException as exc:
            self._report({"kind": "error", "start_time": entry["start_time"], "error": f"{type(exc).__name__}: {exc}"})
            raise
        finally:
            # a robot that cannot say where it is after a failure: the command's error stands
            with contextlib.suppress(Exception):
                self._report(self._state())

    # --- what is logged ---

    def execute_trajectory(self, trajectory: JointTrajectory) -> ExecutionReport:
        check = getattr(self.inner, "check_trajectory", None)  # a real arm's: its limits, its speed scale
        if check is not None:
            try:
                trajectory = check(trajectory)  # the same again when sent: it changes a checked one no further
            except Exception as exc:
                self._report(
                    {"kind": "refused", "start_time": self.inner.time(), "error": f"{type(exc).__name__}: {exc}"}
                )
                raise
        entry = {
            "kind": "trajectory",
            "start_time": self.inner.time(),
            "joint_names": list(self.inner.robot.arm_joints),
            "times": trajectory.times.tolist(),
            "positions": trajectory.positions.tolist(),
            "velocities": trajectory.velocities.tolist(),
        }
        return self._sent(entry, lambda: self.inner.execute_trajectory(trajectory))

    def set_gripper(self, closed: float) -> GripperReport:
        entry = {"kind": "gripper", "start_time": self.inner.time(), "closed": float(closed)}
        return self._sent(entry, lambda: self.inner.set_gripper(closed))

    # --- forwarded ---

    @property
    def robot(self) -> RobotDescription:
        return self.inner.robot

    def joint_positions(self) -> np.ndarray:
        return self.inner.joint_positions()

    def joint_states(self) -> dict[str, float]:
        return self.inner.joint_states()

    def base_pose(self) -> Transform:
        return self.inner.base_pose()

    def tcp_pose(self) -> Transform:
        return self.inner.tcp_pose()

    def gripper_width(self) -> float:
        return self.inner.gripper_width()

    def time(self) -> float:
        return self.inner.time()

    def wait(self, seconds: float) -> None:
        self.inner.wait(seconds)

    def camera_names(self) -> list[str]:
        return self.inner.camera_names()

    def capture(self, camera: str, color: bool = True, segmentation: bool = True) -> CameraFrame:
        return self.inner.capture(camera, color, segmentation)

    def segmentation_labels(self) -> dict[int, str]:
        return self.inner.segmentation_labels()

    def workspace_box(self) -> tuple[np.ndarray, np.ndarray] | None:
        return self.inner.workspace_box()

    def render(self, camera: str, width: int, height: int) -> np.ndarray:
        return self.inner.render(camera, width, height)

    def add_clock_listener(self, listener: ClockListener) -> None:
        self.inner.add_clock_listener(listener)

    def remove_clock_listener(self, listener: ClockListener) -> None:
        self.inner.remove_clock_listener(listener)

    @property
    def ground_truth(self):
        return self.inner.ground_truth

    def close(self) -> None:
        self.inner.close()

    def __getattr__(self, name: str):
        # What is not the interface (a simulator's world, which ground-truth tools read) is the inner backend's.
        if name == "inner":
            raise AttributeError(name)
        return getattr(self.inner, name)
