"""A Franka through libfranka: the franky driver against franky-sim, which serves libfranka's network protocol on
loopback with an FR3 in MuJoCo, as a lab's arm serves it on its network. Both ends are the real third-party code:
franky (with libfranka inside) on this side, franky-sim on the other."""

from __future__ import annotations

import json
import subprocess
import sys
import time

import numpy as np
import pytest

pytest.importorskip("franky", reason="the franky extra is not installed (make test installs it)")
pytest.importorskip("franky_sim", reason="the franky extra is not installed (make test installs it)")

import yaml

from helpers import min_jerk_through
from roboscript.backends.franky import franky_backend
from roboscript.bench.tasks import get_task
from roboscript.drivers.base import DriverError
from roboscript.frankysim.launch import FrankySim
from roboscript.robot_config import config_path, franky_at, load_robot_config
from roboscript.robots import get_robot

BASE = (-0.45, 0.0, 0.82)


def _config(host: str):
    return franky_at(load_robot_config("fr3_franky"), host, realtime=False)


@pytest.fixture(scope="module")
def arm():
    home = get_robot("fr3").home
    with FrankySim(base=BASE, joints=home) as sim:
        backend = franky_backend(_config(sim.host))
        yield backend
        backend.close()


def _move(backend, delta) -> np.ndarray:
    start = backend.joint_positions()
    robot = backend.robot
    trajectory = min_jerk_through(
        np.array([start, start + delta]), np.array(robot.max_velocity), np.array(robot.max_acceleration), 0.25
    )
    backend.execute_trajectory(trajectory)
    return start + delta


def test_the_arm_reads_as_libfranka_reports_it_where_the_configuration_puts_its_base(arm):
    assert arm.config.trajectory_action == arm.config.joint_states == f"libfranka at {arm.config.franky.host}"
    assert np.allclose(arm.joint_positions(), get_robot("fr3").home, atol=0.02)
    assert np.allclose(arm.base_pose().position, BASE)
    states = arm.joint_states()
    assert set(get_robot("fr3").arm_joints) <= set(states)


def test_a_planned_trajectory_runs_through_libfranka_and_ends_where_it_was_planned_to(arm):
    delta = np.zeros(7)
    delta[0], delta[3] = 0.25, -0.15
    target = _move(arm, delta)
    assert np.allclose(arm.joint_positions(), target, atol=0.01)
    target = _move(arm, -delta)
    assert np.allclose(arm.joint_positions(), target, atol=0.01)


def test_the_hand_closes_on_nothing_and_opens_again(arm):
    closed = arm.set_gripper(1.0)
    assert closed.width < 0.01 and not closed.blocked
    opened = arm.set_gripper(0.0)
    assert opened.width > 0.075


def test_no_franka_at_the_address_is_a_clear_error():
    with pytest.raises(DriverError, match=r"no Franka answers at 127\.0\.0\.254"):
        franky_backend(_config("127.0.0.254"))


def test_a_run_from_the_command_line_on_a_franka_that_does_not_answer_names_its_address(tmp_path):
    data = yaml.safe_load(config_path("fr3_franky").read_text())
    data["franky"].update(host="127.0.0.254", realtime="ignore")
    config = tmp_path / "lab.yaml"
    config.write_text(yaml.safe_dump(data))
    program = tmp_path / "program.py"
    program.write_text("open_gripper()\n")
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0"]
    command += ["--backend", "franky", "--robot-config", str(config), "--yes", "--log-dir", str(tmp_path / "run")]
    run = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert run.returncode not in (0, 1), run.stdout
    assert "no Franka answers at 127.0.0.254" in run.stderr, run.stderr[-2000:]


def test_a_cancelled_motion_ends_as_cancelled_and_the_next_one_runs(arm):
    start = arm.joint_positions()
    robot = arm.robot
    long = min_jerk_through(
        np.array([start, start + np.array([-0.6, 0, 0, 0, 0, 0, 0])]),
        np.array(robot.max_velocity),
        np.array(robot.max_acceleration),
        0.1,
    )
    goal = arm.driver.send_trajectory(list(robot.arm_joints), long)
    goal.cancel()
    status = goal.status()
    deadline = time.monotonic() + 120  # libfranka reports it within a few cycles; a loaded machine runs franky-sim slow
    while not status.done and time.monotonic() < deadline:
        time.sleep(0.01)
        status = goal.status()
    assert status.state == "cancelled" and "preempted" in status.detail
    target = _move(arm, np.array([0.1, 0, 0, 0, 0, 0, 0]))
    assert np.allclose(arm.joint_positions(), target, atol=0.01)


def test_a_reflex_ends_the_motion_as_the_robots_error_and_after_recovery_the_next_motion_runs():
    """franky-sim trips a joint reflex mid-motion over libfranka's protocol (the robot in Reflex mode, the motion
    answered ReflexAborted), as a collision would on an FR3: the backend reports it as libfranka said it, the driver
    recovers, and the next motion runs."""
    from roboscript.backends.base import BackendError

    home = get_robot("fr3").home
    with FrankySim(base=BASE, joints=home) as sim:
        backend = franky_backend(_config(sim.host))
        try:
            start = backend.joint_positions()
            sim.trip_reflex()  # for the next motion: it trips as soon as the motion runs
            with pytest.raises(BackendError, match=r"aborted the trajectory: .*reflex.*joint_reflex"):
                _move(backend, np.array([0.4, 0, 0, 0, 0, 0, 0]))
            stopped = backend.joint_positions()
            assert np.max(np.abs(stopped - start)) < 0.3  # held where the reflex stopped it, short of the goal
            target = _move(backend, np.array([0.0, 0, 0, -0.1, 0, 0, 0]))
            assert np.allclose(backend.joint_positions(), target, atol=0.01)
        finally:
            backend.close()


def test_in_a_benchmark_world_franky_sim_runs_the_worlds_fr3_among_its_table_and_objects():
    """The world built as the MuJoCo backend builds it, the arm where the world stands it, driven by franky-sim's
    torques: it holds its home, follows a plan, and its hand closes on nothing and opens."""
    with FrankySim(world="world_2_pick_and_place") as sim:
        backend = franky_backend(_config(sim.host))
        try:
            assert np.allclose(backend.joint_positions(), get_robot("fr3").home, atol=0.01)
            target = _move(backend, np.array([0.3, 0.2, 0.0, -0.2, 0.0, 0.0, 0.0]))
            assert np.allclose(backend.joint_positions(), target, atol=0.01)
            closed = backend.set_gripper(1.0)
            assert not closed.blocked and backend.set_gripper(0.0).width > 0.075
        finally:
            backend.close()


def test_a_mirror_of_franky_sims_world_sees_and_checks_what_franky_sim_runs():
    """The cameras and the checks of a trial through libfranka read franky-sim's world through a mirror built on
    this side and set to franky-sim's state: after a motion the mirror's arm is where libfranka says it is."""
    from roboscript.frankysim.mirror import MirrorCameras, WorldMirror
    from roboscript.sim.world_catalog import load_world

    world = load_world("world_2_pick_and_place")
    with FrankySim(world="world_2_pick_and_place") as sim:
        mirror = WorldMirror(sim, world)
        cameras = MirrorCameras(mirror)
        backend = franky_backend(_config(sim.host), cameras=cameras)
        try:
            assert backend.camera_names() == ["camera_left", "camera_right", "camera_top"]
            target = _move(backend, np.array([0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]))
            frame = backend.capture("camera_top")
            arm = mirror.world.robot.qpos
            # read one after the other while the arm still settles (within 5 mrad of the plan: the goal tolerance)
            assert np.allclose(mirror.world.data.qpos[arm], backend.joint_positions(), atol=5e-3)
            assert np.allclose(mirror.world.data.qpos[arm], target, atol=0.01)
            assert frame.rgb.shape == (480, 640, 3) and frame.segmentation is None
            assert (frame.depth > 0).mean() > 0.9  # the table fills the top camera's view
            apple = mirror.ground_truth.pose("apple").position
            assert 0.8 < apple[2] < 0.9  # still on the table (0.82 m) after the world came up under franky-sim
        finally:
            backend.close()
            cameras.close()


def test_the_papers_simple_0_runs_through_libfranka_seeing_only_the_cameras(tmp_path):
    """The end-to-end proof: the reference program of "place the apple into the footed bowl" through franky and
    libfranka's protocol to franky-sim, with full perception (nothing of the simulator's state reaches the tools),
    and the task's check read from franky-sim's world on this side."""
    program = tmp_path / "simple_0.py"
    program.write_text(get_task("simple_0").reference_program())
    command = [
        sys.executable,
        "-m",
        "roboscript.cli",
        "exec",
        str(program),
        "--task",
        "simple_0",
        "--backend",
        "franky",
    ]
    run = subprocess.run(
        [*command, "--robot", "fr3", "--trials", "1", "--json"], capture_output=True, text=True, timeout=900
    )
    assert run.returncode == 0, run.stderr[-2000:]
    result = json.loads(run.stdout)
    assert result["whole_task_success"] == 1.0, run.stdout[-3000:]
