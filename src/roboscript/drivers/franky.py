"""A Franka arm and hand driven through libfranka with franky (the ``franky`` extra), without ROS.

A planned joint trajectory goes to the arm as one franky ``JointWaypointMotion`` through its samples, each with
the planned velocity and no less than the planned time since the last, so libfranka's own trajectory generator
keeps to the plan's path and pace. Joint states are libfranka's, read when asked; a state counts as received when
the robot's clock last moved. The robot's own errors (reflexes, limits) end a motion as ``aborted`` with what
libfranka said, and the driver asks libfranka to recover from them so that the next motion can run. Cameras come
from a :class:`~roboscript.drivers.base.CameraSource`: the configuration's RealSense cameras unless one is given.
"""

from __future__ import annotations

import logging
import threading
import time

import numpy as np

from roboscript import extras
from roboscript.drivers.base import (
    CameraSource,
    Driver,
    DriverError,
    GoalStatus,
    GripperResult,
    JointStateReading,
    TrackingSample,
    TrajectoryGoal,
)
from roboscript.drivers.realsense import RealSenseCameras
from roboscript.robot_config import RobotConfig
from roboscript.robot_io import CameraFrame
from roboscript.trajectory import JointTrajectory

log = logging.getLogger(__name__)

WAYPOINT_SPACING = 0.05  # seconds of the plan between waypoints sent (the plan's own samples are denser)
GOAL_TOLERANCE = 0.005  # radians from the plan's last positions within which the arm counts as arrived
SETTLE_TIME = 1.0  # robot seconds a finished motion is given to come within GOAL_TOLERANCE (a FollowJointTrajectory's
# goal time tolerance): the simulator's arm lags its set-point by up to 0.02 rad as a motion ends
# metres either side of the commanded width within which libfranka's grasp "succeeds": wide, so that closing on
# anything or nothing is not an error (whether something is held is told from the width)
GRASP_TOLERANCE = 0.08
HAND_EMPTY = 0.004  # metres: a hand closed on nothing stops within this (franky-sim's at 1.6 to 2.3 mm)
RECOVERY_READS = 20  # fresh states read, 10 ms apart, to see a recovery's errors cleared before calling it failed


def _franky():
    try:
        import franky
    except ImportError as error:
        raise DriverError(extras.missing_text("franky", "a Franka through libfranka")) from error
    return franky


class _Motion(TrajectoryGoal):
    """A motion sent to the arm: done when libfranka says so, aborted with its exception."""

    def __init__(self, driver: FrankyDriver, last: np.ndarray):
        self._driver, self._last = driver, last  # the plan's last positions, in libfranka's joint order
        self._final: GoalStatus | None = None
        self._ended_at: float | None = None  # robot time libfranka said the motion ended

    def tracking(self) -> TrackingSample | None:
        state = self._driver.robot_state()
        return TrackingSample(np.array(state.q_d), np.array(state.q))

    def status(self) -> GoalStatus:
        if self._final is None:  # libfranka reports an ending once: keep it
            status = self._driver.motion_status()
            if not status.done:
                return status
            self._final, self._ended_at = status, self._driver.now()
        if self._final.state == "succeeded" and not self._settled():
            return GoalStatus("active")
        return self._final

    def _settled(self) -> bool:
        # against the plan's end: once a motion has ended, libfranka's set-point is wherever the arm is
        off = float(np.max(np.abs(np.array(self._driver.robot_state().q) - self._last)))
        return off <= GOAL_TOLERANCE or self._driver.now() - self._ended_at >= SETTLE_TIME

    def cancel(self) -> None:
        self._driver.stop_motion()


class FrankyDriver(Driver):
    """The Franka arm and hand at ``config.franky.host``; ``cameras`` default to the configuration's RealSense ones."""

    def __init__(self, config: RobotConfig, cameras: CameraSource | None = None):
        if config.franky is None:
            raise DriverError(
                f"robot configuration {config.name!r} has no 'franky' section (its driver is {config.driver})"
            )
        franky = _franky()
        self.config, self._franky = config, franky
        settings = config.franky
        realtime = franky.RealtimeConfig.Enforce if settings.realtime else franky.RealtimeConfig.Ignore
        try:
            self._robot = franky.Robot(settings.host, realtime_config=realtime)
            self._gripper = franky.Gripper(settings.host)
        except franky.RealtimeException as error:
            raise DriverError(
                f"libfranka needs a real-time kernel here ({error}): run on one, or set realtime: ignore in "
                f"{config.source or config.name} (at your own risk on a real arm)"
            ) from None
        except (franky.Exception, franky.GripperException) as error:
            raise DriverError(
                f"no Franka answers at {settings.host} ({type(error).__name__}: {error}): is the arm's control "
                "interface (FCI) enabled in Desk, and is this its address? (franky-sim: is it running?)"
            ) from None
        self._lock = threading.Lock()
        self._stopping = False  # a stop was asked for: the motion's end is a cancellation, not a fault
        self._clock: tuple[float, float] | None = None  # (robot time, monotonic time when it last moved)
        self._width = float(self._gripper.width)
        self._names = list(config.robot.arm_joints)
        self._cameras = cameras if cameras is not None else RealSenseCameras(config.cameras)

    # --- state ---

    def robot_state(self):
        """libfranka's latest robot state (``franky.RobotState``); a DriverError where libfranka has lost the arm."""
        try:
            with self._lock:
                return self._robot.state
        except self._franky.Exception as error:
            raise DriverError(
                f"libfranka lost the arm at {self.config.franky.host}: {type(error).__name__}: {error}"
            ) from None

    def joint_state(self) -> JointStateReading | None:
        state = self.robot_state()
        robot_time = float(state.time.to_sec())
        now = time.monotonic()
        if self._clock is None or robot_time != self._clock[0]:
            self._clock = (robot_time, now)
        positions = {self.config.driver_joint(j): float(q) for j, q in zip(self._names, state.q, strict=True)}
        for joint in self.config.gripper.width_joints:
            positions[joint] = self._width / len(self.config.gripper.width_joints)
        return JointStateReading(positions, robot_time, self._clock[1])

    def now(self) -> float:
        """The robot's clock (libfranka's, in seconds): a simulated arm's runs slower than the wall's under load,
        and the backend times motions by it."""
        return float(self.robot_state().time.to_sec())

    # --- motion ---

    def send_trajectory(self, joint_names: list[str], trajectory: JointTrajectory) -> TrajectoryGoal:
        franky = self._franky
        order = [joint_names.index(self.config.driver_joint(j)) for j in self._names]
        waypoints = [
            franky.JointWaypoint(franky.JointState(q[order], dq[order]), minimum_time=franky.Duration(ms))
            for ms, q, dq in zip(*waypoint_samples(trajectory, WAYPOINT_SPACING), strict=True)
        ]
        self._stopping = False  # a stop asked for an earlier motion is not this one's
        try:
            with self._lock:
                self._robot.move(franky.JointWaypointMotion(waypoints), asynchronous=True)
        except (franky.Exception, RuntimeError) as error:
            raise DriverError(f"libfranka refused the motion: {type(error).__name__}: {error}") from None
        return _Motion(self, np.asarray(trajectory.positions[-1])[order])

    def motion_status(self) -> GoalStatus:
        """Where the last motion stands (``active`` while it runs); recovers from the robot's errors once reported."""
        franky = self._franky
        try:
            with self._lock:
                finished = self._robot.poll_motion()  # true once the motion has ended; raises what ended it
        except (franky.Exception, RuntimeError) as error:  # libfranka's, and its trajectory generator's
            detail = f"{type(error).__name__}: {error}"
            recovered = self._recover()
            state = "cancelled" if self._stopping else "aborted"  # a stop ends the motion with libfranka's error
            self._stopping = False
            return GoalStatus(state, detail + ("" if recovered else "; libfranka could not recover from it"))
        if finished:
            self._stopping = False
        elif self._stopping:  # a stop sent before libfranka's control loop ran preempts nothing: send it again
            self._stop()
        return GoalStatus("succeeded") if finished else GoalStatus("active")

    def stop_motion(self) -> None:
        """Stops the running motion, if any (the arm holds where it is)."""
        self._stopping = True
        self._stop()

    def _stop(self) -> None:
        try:
            with self._lock:
                self._robot.stop()
        except self._franky.Exception as error:
            log.warning("stopping the arm: %s", error)

    def _recover(self) -> bool:
        try:
            with self._lock:
                if self._robot.recover_from_errors():
                    return True
            # libfranka judged the recovery on the newest state it held, which can predate the recovery's answer:
            # judge it again on states read after it (the lock not held while waiting for them)
            for _ in range(RECOVERY_READS):
                time.sleep(0.01)
                with self._lock:
                    if not self._robot.has_errors:
                        return True
            return False
        except self._franky.Exception as error:
            log.warning("recovering from the robot's errors: %s", error)
            return False

    def command_gripper(self, position: float, closing: bool, timeout: float) -> GripperResult:
        gripper = self.config.gripper
        try:
            if closing:
                future = self._gripper.grasp_async(
                    position, gripper.speed, gripper.max_effort, GRASP_TOLERANCE, GRASP_TOLERANCE
                )
            else:
                future = self._gripper.move_async(position, gripper.speed)
            if not future.wait(timeout):
                self._gripper.stop()
                raise DriverError(f"the Franka hand did not finish within {timeout:.1f} s; it was stopped")
            reached = bool(future.get())
            self._width = float(self._gripper.width)
        except (self._franky.Exception, self._franky.GripperException) as error:
            raise DriverError(f"the Franka hand failed: {type(error).__name__}: {error}") from None
        # libfranka's "grasped" only says the width ended within the tolerances of the one commanded (here: closed);
        # whether the fingers stopped on something is told from the width
        return GripperResult(self._width, stalled=closing and self._width > HAND_EMPTY, reached=reached)

    # --- cameras ---

    def camera_names(self) -> list[str]:
        return self._cameras.names()

    def camera_frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        # the cameras stamp frames on this host's monotonic clock, not the robot's
        return self._cameras.frame(camera, timeout, time.monotonic() - (self.now() - not_before))

    def close(self) -> None:
        try:
            self.stop_motion()
        finally:
            self._cameras.close()


def waypoint_samples(trajectory: JointTrajectory, spacing: float) -> tuple[list[int], np.ndarray, np.ndarray]:
    """The plan as franky's waypoints: ``(milliseconds since the last, positions, velocities)`` at even steps of
    about ``spacing`` seconds after the start, the last at the plan's end, at rest.

    Even steps, interpolated from the plan, rather than the plan's own samples: those are uneven (a
    time-parameterised plan ends with a long, slow one), and on some of them the trajectory generator inside franky
    (Ruckig) failed to synchronise the joints ("Motion planner failed with error code -111"), aborting the motion.
    It did so in 4 of 10 trials of simple_0 through franky-sim; the same motions, resampled evenly, ran."""
    span = float(trajectory.times[-1] - trajectory.times[0])
    steps = max(1, int(np.ceil(span / spacing - 1e-9)))
    times = trajectory.times[0] + np.linspace(0.0, span, steps + 1)[1:]
    positions, velocities, _ = trajectory.sample_many(times)
    velocities[-1] = 0.0
    stamps = np.round(1000 * (times - trajectory.times[0])).astype(int)
    return np.diff(stamps, prepend=0).tolist(), positions, velocities
