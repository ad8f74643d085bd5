"""A backend over a driver: the :class:`Backend` interface, and the safety a real arm needs, for any transport.

Before a trajectory is sent it is checked against the joint limits, the configuration's speed scale (a faster one is
slowed down, never sent as it is), the workspace box (every link) and the table's height (the TCP). While it runs,
the joint states and the controller's feedback are watched: the goal is cancelled when a joint lags its set-point
(as the controller reports both, in step) by more than the tracking tolerance, when joint states stop arriving,
when the controller does not finish in time, and on Ctrl-C; each ends in an error that says what happened, within
the configuration's timeouts.
"""

from __future__ import annotations

import contextlib
import time as _time
from collections.abc import Callable

import numpy as np

from roboscript.backends.base import Backend, BackendError
from roboscript.drivers.base import Driver, DriverError, JointStateReading
from roboscript.geometry import Transform
from roboscript.load import load_factor
from roboscript.robot_config import RobotConfig
from roboscript.robot_io import CameraFrame, ExecutionReport, GripperReport
from roboscript.robots import RobotDescription
from roboscript.robots.mujoco_model import RobotModel
from roboscript.trajectory import JointTrajectory

POLL = 0.01  # seconds between checks of a running motion
START_TOLERANCE = 0.05  # radians a trajectory's first point may be from where the arm is
CHECK_STEP = 0.05  # seconds between the trajectory samples checked against the workspace
FIRST_STATE_TIMEOUT = 2.0  # seconds to wait for the first joint state
EMPTY_GRIP = 0.002  # metres: fingers closed this far hold nothing
SET_POINT_MOVED = 1e-5  # radians: a controller's set-point that moved less than this has not progressed
GRIPPER_SETTLE = 0.05  # seconds after a gripper's result: the opening is then read from a joint state after it


class MotionRefused(BackendError):
    """A trajectory was not sent: it would break a safety limit (workspace, table, joint limits)."""


class DriverBackend(Backend):
    """A robot reached through ``driver`` as ``config`` describes it.

    ``base_pose``: where the robot's base is in the world frame (from TF on ROS). ``confirm`` is asked once, before
    the first motion; a false answer refuses it.
    """

    def __init__(
        self,
        driver: Driver,
        config: RobotConfig,
        base_pose: Transform,
        confirm: Callable[[str], bool] | None = None,
    ):
        self.driver, self.config = driver, config
        self._base_pose = base_pose
        self._model = RobotModel(config.robot, base_pose)
        self._confirm = confirm
        # driver joint name -> the model's (unmapped names are the model's own)
        self._model_names = {driver: model for model, driver in config.joint_names.items()}
        self._arm = config.arm_driver_joints()
        self._wait_for_first_state()
        self._still_since = driver.now()  # robot clock: since when nothing we commanded has moved

    # --- state ---

    @property
    def robot(self) -> RobotDescription:
        return self.config.robot

    def _wait_for_first_state(self) -> None:
        deadline = _time.monotonic() + FIRST_STATE_TIMEOUT
        while self.driver.joint_state() is None:
            if _time.monotonic() > deadline:
                raise DriverError(
                    f"no joint states on {self.config.joint_states} within {FIRST_STATE_TIMEOUT:.0f} s: is the robot's "
                    "driver running, and is this the topic it publishes?"
                )
            _time.sleep(POLL)
        missing = [j for j in self._arm if j not in self.driver.joint_state().positions]
        if missing:
            raise DriverError(
                f"the joint states on {self.config.joint_states} lack {', '.join(missing)}; they hold "
                f"{', '.join(sorted(self.driver.joint_state().positions))} (map the model's joints to these names "
                f"under 'joints' in {self.config.source or 'the robot configuration'})"
            )

    def _fresh_state(self, patience: float | None = None) -> JointStateReading:
        """The latest joint state, if it is recent enough. While the arm stands still a stale one is waited on for
        ``patience`` seconds (default: twice the state timeout, scaled by the machine's load as every wall-clock
        budget is, :func:`~roboscript.load.load_factor`) before it counts as lost: after a long computation in this
        process (fusing depth images holds the interpreter), or on a machine busier than its cores, the
        subscriber's thread or the robot's publisher may simply not have run yet. During a motion there is no
        patience: the arm is stopped at once."""
        patience = 2 * self.config.state_timeout * load_factor() if patience is None else patience
        deadline = _time.monotonic() + patience
        while True:
            reading = self.driver.joint_state()
            age = _time.monotonic() - reading.received
            if age <= self.config.state_timeout:
                return reading
            if _time.monotonic() >= deadline:
                raise DriverError(
                    f"joint states are stale: the last one on {self.config.joint_states} arrived {age:.2f} s ago "
                    f"(more than the {self.config.state_timeout} s allowed); the robot's driver or the connection "
                    "is down"
                )
            _time.sleep(POLL)

    def joint_states(self) -> dict[str, float]:
        positions = self._fresh_state().positions
        return {self._model_names.get(name, name): value for name, value in positions.items()}

    def joint_positions(self) -> np.ndarray:
        positions = self._fresh_state().positions
        return np.array([positions[j] for j in self._arm])

    def base_pose(self) -> Transform:
        return self._base_pose

    def tcp_pose(self) -> Transform:
        return self._model.tcp(self.joint_positions())

    def gripper_width(self) -> float:
        gripper = self.config.gripper
        positions = self._fresh_state().positions
        return gripper.width_scale * sum(positions[j] for j in gripper.width_joints) + gripper.width_offset

    def time(self) -> float:
        return self.driver.now()

    # --- motion ---

    def workspace_box(self) -> tuple[np.ndarray, np.ndarray]:
        workspace = self.config.workspace
        return np.array(workspace.lower, dtype=float), np.array(workspace.upper, dtype=float)

    def check_trajectory(self, trajectory: JointTrajectory) -> JointTrajectory:
        """The trajectory as it will be sent (slowed to the speed scale), or :class:`MotionRefused` saying which
        limit it would break and where."""
        robot, workspace = self.config.robot, self.config.workspace
        if trajectory.dof != robot.dof:
            raise MotionRefused(f"trajectory has {trajectory.dof} joints, the {robot.name} arm {robot.dof}")
        start = self.joint_positions()
        offset = float(np.max(np.abs(trajectory.positions[0] - start)))
        if offset > START_TOLERANCE:
            raise MotionRefused(
                f"trajectory starts {offset:.3f} rad away from where the arm is (at most {START_TOLERANCE} allowed)"
            )
        low, high = self._model.joint_lower - 1e-6, self._model.joint_upper + 1e-6
        beyond = np.argwhere((trajectory.positions < low) | (trajectory.positions > high))
        if len(beyond):
            i, j = beyond[0]
            raise MotionRefused(
                f"trajectory takes {robot.arm_joints[j]} to {trajectory.positions[i, j]:.3f} rad at "
                f"t={trajectory.times[i]:.2f} s, outside its limits [{low[j]:.3f}, {high[j]:.3f}]"
            )
        trajectory = self._within_speed(trajectory)
        times = np.unique(np.append(np.arange(0.0, trajectory.duration, CHECK_STEP), trajectory.duration))
        for t, q in zip(times, trajectory.sample_many(times)[0], strict=True):
            tcp = self._model.tcp(q).position
            if tcp[2] < workspace.table_height:
                raise MotionRefused(
                    f"trajectory takes the TCP to z={tcp[2]:.3f} m at t={t:.2f} s, below the table's top at "
                    f"{workspace.table_height} m"
                )
            for name, point in zip(self._model.link_names, self._model.link_positions(q), strict=True):
                if not workspace.contains(point):
                    raise MotionRefused(
                        f"trajectory would leave the workspace: {name} at ({point[0]:.3f}, {point[1]:.3f}, "
                        f"{point[2]:.3f}) at t={t:.2f} s, outside the box {workspace.lower} .. {workspace.upper}"
                    )
        return trajectory

    def _within_speed(self, trajectory: JointTrajectory) -> JointTrajectory:
        """``trajectory`` slowed down uniformly until no joint exceeds the speed scale of its velocity limit."""
        limit = np.asarray(self.config.robot.max_velocity) * self.config.speed_scale
        peak = float(np.max(np.abs(trajectory.velocities) / limit))
        if peak <= 1.0:
            return trajectory
        return JointTrajectory(trajectory.times * peak, trajectory.positions, trajectory.velocities / peak)

    def execute_trajectory(self, trajectory: JointTrajectory) -> ExecutionReport:
        trajectory = self.check_trajectory(trajectory)
        if self._confirm is not None:
            confirm, self._confirm = self._confirm, None
            if not confirm(f"move the {self.config.robot.name} ({trajectory.duration:.1f} s trajectory)?"):
                raise MotionRefused("the first motion was not confirmed; nothing moved")
        goal = self.driver.send_trajectory(self._arm, trajectory)
        started = self.driver.now()
        deadline = trajectory.duration + self.config.server_timeout
        joint_errors, tcp_errors = [], []
        seen = None  # the feedback last judged: it comes at the controller's rate, slower than this loop polls
        # when the controller's set-point last moved: a controller running behind the plan's time (a simulated
        # arm on a busy machine) is waited for while it keeps moving, not cut off at the plan's end
        progressed, set_point = started, None
        try:
            while True:
                status = goal.status()
                if status.done:
                    break
                self._fresh_state_or_stop(goal)
                now = self.driver.now()
                elapsed = now - started
                sample = goal.tracking()  # the controller's own set-point and measurement, in step with each other
                if sample is not None and sample is not seen:
                    seen = sample
                    if set_point is None or np.max(np.abs(sample.desired - set_point)) > SET_POINT_MOVED:
                        progressed, set_point = now, sample.desired
                    lag = np.abs(sample.actual - sample.desired)
                    joint_errors.append(float(np.max(lag)))
                    tcp_errors.append(self._tcp_distance(sample.actual, sample.desired))
                    if joint_errors[-1] > self.config.tracking_tolerance:
                        joint = self.config.driver_joint(self.config.robot.arm_joints[int(np.argmax(lag))])
                        self._stop(goal)
                        raise BackendError(
                            f"tracking lost: {joint} is {joint_errors[-1]:.3f} rad from its set-point at "
                            f"t={elapsed:.2f} s (tolerance {self.config.tracking_tolerance} rad); the goal was "
                            "cancelled and the arm stopped"
                        )
                stalled = now - progressed > self.config.server_timeout
                if elapsed > deadline and (stalled or set_point is None):
                    self._stop(goal)
                    raise BackendError(
                        f"the controller at {self.config.trajectory_action} did not finish a {trajectory.duration:.1f} "
                        f"s trajectory within {self.config.server_timeout} s of its end"
                        + ("" if set_point is None else f" (its set-point still for {self.config.server_timeout} s)")
                        + "; the goal was cancelled"
                    )
                self._clock_advanced(self.driver.now())
                _time.sleep(POLL)
        except KeyboardInterrupt:
            self._stop(goal)
            raise
        if status.state != "succeeded":
            raise BackendError(
                f"the controller at {self.config.trajectory_action} {status.state} the trajectory"
                + (f": {status.detail}" if status.detail else "")
            )
        self._still_since = self.driver.now()
        final = self.joint_positions()
        end = trajectory.positions[-1]
        return ExecutionReport(
            duration=self.driver.now() - started,
            max_joint_error=max(joint_errors, default=0.0),
            max_tcp_error=max(tcp_errors, default=0.0),
            final_joint_error=float(np.max(np.abs(final - end))),
            final_tcp_error=self._tcp_distance(final, end),
        )

    def _tcp_distance(self, a: np.ndarray, b: np.ndarray) -> float:
        return float(np.linalg.norm(self._model.tcp(a).position - self._model.tcp(b).position))

    def _fresh_state_or_stop(self, goal) -> JointStateReading:
        try:
            return self._fresh_state(patience=0.0)
        except DriverError:
            self._stop(goal, confirmed=False)  # nothing is heard from the robot: no confirmation will come either
            raise

    def _stop(self, goal, confirmed: bool = True) -> None:
        """Cancels ``goal``; with ``confirmed``, waits (on the wall clock, up to the server timeout) for the controller
        to say it stopped. A server that is gone has nothing left to cancel, and the error being raised says why."""
        with contextlib.suppress(DriverError):
            goal.cancel()
            deadline = _time.monotonic() + self.config.server_timeout
            while confirmed and not goal.status().done and _time.monotonic() < deadline:
                _time.sleep(POLL)

    def set_gripper(self, closed: float) -> GripperReport:
        if not 0.0 <= closed <= 1.0:
            raise BackendError(f"gripper command must be in [0, 1] (0 open, 1 closed), got {closed}")
        gripper = self.config.gripper
        position = gripper.open_position + closed * (gripper.closed_position - gripper.open_position)
        started = self.driver.now()
        result = self.driver.command_gripper(position, closing=closed > 0.5, timeout=self.config.server_timeout + 3.0)
        self.wait(GRIPPER_SETTLE)
        self._still_since = self.driver.now()
        width = self.gripper_width()
        blocked = result.stalled if result.stalled is not None else closed > 0.5 and width > EMPTY_GRIP
        return GripperReport(width, closed, blocked, self.driver.now() - started)

    def wait(self, seconds: float) -> None:
        until = self.driver.now() + seconds
        while self.driver.now() < until:
            self._fresh_state()
            self._clock_advanced(self.driver.now())
            _time.sleep(POLL)

    # --- sensing ---

    def camera_names(self) -> list[str]:
        return self.driver.camera_names()

    def capture(self, camera: str, color: bool = True, segmentation: bool = True) -> CameraFrame:
        if camera not in self.camera_names():
            raise BackendError(f"no camera named {camera!r}; cameras: {', '.join(self.camera_names()) or 'none'}")
        # A frame from before the last motion ended would show the world as it was.
        timeout = self.config.server_timeout + 2.0
        try:
            return self.driver.camera_frame(camera, timeout, self._still_since)
        except DriverError:
            # A busy machine (or network) delays images more than a wait on the clock allows for: wait once more,
            # twice as long, before calling the camera lost.
            return self.driver.camera_frame(camera, 2 * timeout, self._still_since)

    def segmentation_labels(self) -> dict[int, str]:
        return self.driver.segmentation_labels()

    def close(self) -> None:
        self.driver.close()
