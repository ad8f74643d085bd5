"""How long the backend waits for a controller to finish a trajectory: past the plan's end for as long as the
controller's set-point keeps moving (a simulated arm on a busy machine runs behind the plan's time), and no longer
than the server timeout once it has stopped moving short of the end."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from helpers import ArmOnlyDriver
from roboscript.backends.base import BackendError
from roboscript.backends.driven import DriverBackend
from roboscript.drivers.base import GoalStatus, JointStateReading, TrackingSample, TrajectoryGoal
from roboscript.geometry import Transform
from roboscript.robot_config import load_robot_config
from roboscript.trajectory import JointTrajectory

ON_THE_TABLE = Transform(np.array([-0.45, 0.0, 0.82]), np.array([0.0, 0.0, 0.0, 1.0]))  # the arm's base


class PacedController(TrajectoryGoal):
    """Test double of a controller that plays the plan at ``pace`` times the robot's clock, its set-point standing
    still from ``stall_at`` (a fraction of the plan) on."""

    def __init__(self, driver: PacedDriver, trajectory: JointTrajectory, pace: float, stall_at: float):
        self.driver, self.trajectory, self.pace = driver, trajectory, pace
        self.start = driver.now()
        self.stop_at = stall_at * trajectory.duration

    def plan_time(self) -> float:
        return min((self.driver.now() - self.start) * self.pace, self.stop_at, self.trajectory.duration)

    def set_point(self) -> np.ndarray:
        return self.trajectory.sample(self.plan_time())[0]

    def tracking(self) -> TrackingSample:
        q = self.set_point()
        return TrackingSample(q, q)

    def status(self) -> GoalStatus:
        return GoalStatus("succeeded" if self.plan_time() >= self.trajectory.duration else "active")

    def cancel(self) -> None:
        self.stop_at = self.plan_time()


class PacedDriver(ArmOnlyDriver):
    """Test double of a driver whose controller is a :class:`PacedController`; its arm is wherever the
    controller's set-point is."""

    def __init__(self, names: list[str], start: np.ndarray, pace: float, stall_at: float = 1.0):
        self.names, self.start, self.pace, self.stall_at = names, start, pace, stall_at
        self.goal: PacedController | None = None

    def joint_state(self) -> JointStateReading:
        q = self.goal.set_point() if self.goal is not None else self.start
        positions = dict(zip(self.names, [*q, 0.04, 0.04], strict=False))
        return JointStateReading(positions, self.now(), self.now())

    def send_trajectory(self, joint_names, trajectory):
        self.goal = PacedController(self, trajectory, self.pace, self.stall_at)
        return self.goal


def _backend(pace: float, stall_at: float = 1.0) -> tuple[DriverBackend, JointTrajectory]:
    config = dataclasses.replace(load_robot_config("panda_franka_ros"), server_timeout=0.3)
    names = [*config.arm_driver_joints(), *config.gripper.width_joints]
    start = np.array(config.robot.home)
    backend = DriverBackend(PacedDriver(names, start, pace, stall_at), config, ON_THE_TABLE)
    end = start + np.array([0.02, 0, 0, 0, 0, 0, 0])
    times = np.linspace(0.0, 0.4, 9)
    positions = start + np.outer(times / 0.4, end - start)
    velocities = np.tile((end - start) / 0.4, (9, 1))
    velocities[0] = velocities[-1] = 0.0
    return backend, JointTrajectory(times, positions, velocities)


def test_a_controller_running_at_half_the_plans_pace_is_waited_for_while_it_moves():
    backend, plan = _backend(pace=0.5)  # it ends 0.4 s after the plan's end, past the 0.3 s server timeout
    report = backend.execute_trajectory(plan)
    assert report.duration > plan.duration + backend.config.server_timeout
    assert report.final_joint_error < 1e-6


def test_a_controller_whose_set_point_stops_short_of_the_end_is_cut_off_after_the_server_timeout():
    backend, plan = _backend(pace=1.0, stall_at=0.5)
    with pytest.raises(BackendError, match=r"did not finish a 0\.4 s trajectory within 0\.3 s of its end \(its "):
        backend.execute_trajectory(plan)


def test_a_logged_arm_logs_a_trajectory_as_its_checks_send_it_and_a_refused_one_as_refused():
    from roboscript.backends.driven import MotionRefused
    from roboscript.backends.logged import LoggedBackend

    backend, plan = _backend(pace=1.0)
    entries: list[dict] = []
    logged = LoggedBackend(backend, entries.append)
    fast = JointTrajectory(plan.times / 20, plan.positions, plan.velocities * 20)  # beyond the speed scale
    logged.execute_trajectory(fast)
    sent = logged.commands[-1]
    assert sent["times"][-1] == pytest.approx(backend.check_trajectory(fast).duration)
    assert sent["times"][-1] > fast.duration * 1.5  # slowed as the arm was sent it, not as the program planned it
    start = backend.joint_positions()
    past_its_limit = JointTrajectory(
        np.array([0.0, 1.0]), np.array([start, start + np.array([3.0, 0, 0, 0, 0, 0, 0])]), np.zeros((2, 7))
    )
    with pytest.raises(MotionRefused):
        logged.execute_trajectory(past_its_limit)
    assert [e["kind"] for e in entries] == ["state", "trajectory", "state", "refused"]
    assert len(logged.commands) == 1  # what was refused was never sent
