"""A program on a robot that is already running: `roboscript exec --backend ros --master URI` against a
`roboscript ros-sim` started beforehand, as a user would drive a real arm.

- ``--dry-run`` looks, builds the twin of the scene as perceived, runs the pick and place there, writes the planned
  trajectories, and sends the robot nothing;
- ``--validate-in-sim`` does not send a program that fails on the twin;
- a validated program runs on the robot, and its log (a rosbag) holds the goals, joint states and tool calls, and
  replays on the twin where the robot went;
- without a terminal the first motion cannot be confirmed: the run is refused unless ``--yes``.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("rospy", reason="ROS 1 is not installed here (scripts/setup.sh installs it on Debian)")

from roboscript.bench.tasks import get_task
from roboscript.replay import read_run_log, replay_on_twin
from roboscript.ros.launch import start_master, start_sim

WORLD = "world_2_pick_and_place"
SMALL_MOTIONS = """\
open_gripper()
move_in_direction(direction=[0, 0, 1], distance=0.05)
close_gripper()
open_gripper()
"""
INTO_THE_TABLE = "move_in_direction(direction=[0, 0, -1], distance=0.6)\n"


def _exec(program: Path, uri: str, *flags: str, stdin=subprocess.DEVNULL) -> tuple[subprocess.CompletedProcess, dict]:
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--world", WORLD, "--backend", "ros"]
    run = subprocess.run(
        [*command, "--master", uri, "--json", *flags], capture_output=True, text=True, timeout=900, stdin=stdin
    )
    lines = run.stdout.strip().splitlines()
    return run, json.loads(lines[-1]) if run.returncode in (0, 1) and lines else {}


@pytest.fixture(scope="module")
def running_robot(tmp_path_factory):
    """A master and ros-sim of their own (this process's ROS node stays off them: the runs are subprocesses)."""
    master, uri = start_master(str(tmp_path_factory.mktemp("ros_home")))
    sim = start_sim(WORLD, "panda", uri, real_time_factor=2.0)
    yield uri
    sim.stop()
    master.terminate()
    master.wait(timeout=10)


@pytest.mark.slow
def test_a_dry_run_plans_the_pick_and_place_on_the_twin_and_sends_nothing(running_robot, tmp_path):
    program = tmp_path / "simple_0.py"
    program.write_text(get_task("simple_0").reference_program())
    run, result = _exec(program, running_robot, "--dry-run", "--log-dir", str(tmp_path / "dry"))
    assert run.returncode == 0, run.stderr[-3000:]
    assert result["ok"] and not result["sent"] and result["twin"]["outcome"] == "ok", result
    assert "2 objects (apple, footed_bowl)" in result["twin"]["scene"]
    planned = json.loads((tmp_path / "dry" / "twin" / "plan.json").read_text())["commands"]
    assert [c["kind"] for c in planned].count("trajectory") >= 4
    assert [c["closed"] for c in planned if c["kind"] == "gripper"] == [0.0, 1.0, 0.0]
    record = read_run_log(tmp_path / "dry" / "run.bag")
    assert record.commands == []  # no goal ever reached the robot's action servers
    assert np.abs(record.states[-1] - record.states[0]).max() < 1e-3
    assert record.run["dry_run"] and record.outcome["stopped"].startswith("dry run")


@pytest.mark.slow
def test_a_program_that_fails_on_the_twin_is_not_sent(running_robot, tmp_path):
    program = tmp_path / "into_the_table.py"
    program.write_text(INTO_THE_TABLE)
    run, result = _exec(program, running_robot, "--validate-in-sim", "--yes", "--log-dir", str(tmp_path / "bad"))
    assert run.returncode == 1, run.stderr[-3000:]
    assert not result["sent"] and result["stopped"].startswith("not sent: the program failed on the twin"), result
    assert result["twin"]["outcome"] != "ok"
    assert read_run_log(tmp_path / "bad" / "run.bag").commands == []


@pytest.mark.slow
def test_a_validated_run_is_logged_and_its_log_replays_on_the_twin(running_robot, tmp_path):
    program = tmp_path / "small.py"
    program.write_text(SMALL_MOTIONS)
    run, result = _exec(program, running_robot, "--validate-in-sim", "--yes", "--log-dir", str(tmp_path / "run"))
    assert run.returncode == 0, run.stderr[-3000:]
    assert result["ok"] and result["sent"] and result["outcome"] == "ok", result
    record = read_run_log(tmp_path / "run" / "run.bag")
    assert [c.kind for c in record.commands] == ["gripper", "trajectory", "gripper", "gripper"]
    assert [c["tool"] for c in record.tool_calls] == [
        "open_gripper",
        "move_in_direction",
        "close_gripper",
        "open_gripper",
    ]
    assert record.tool_calls[1]["kwargs"] == {"direction": [0, 0, 1], "distance": 0.05}
    lifted = record.state_before(record.commands[2].time)
    assert np.abs(lifted - record.states[0]).max() > 0.01  # the arm moved on the robot
    steps = replay_on_twin(record, WORLD)
    assert all(s.twin_error is None for s in steps), steps
    assert max(s.deviation for s in steps) < 0.02  # the twin went where the robot went


def test_without_a_terminal_the_first_motion_needs_yes(tmp_path):
    program = tmp_path / "small.py"
    program.write_text(SMALL_MOTIONS)
    run, _ = _exec(program, "http://127.0.0.1:9", "--validate-in-sim")  # refused before it connects anywhere
    assert run.returncode == 2
    assert "must be confirmed" in run.stderr and "--yes" in run.stderr


def test_an_unreachable_master_ends_the_run_with_its_address_instead_of_retrying(tmp_path):
    """rospy retries an absent master for ever; the run asks the master itself first, with a time limit."""
    program = tmp_path / "small.py"
    program.write_text(SMALL_MOTIONS)
    run, _ = _exec(program, "http://127.0.0.1:9", "--dry-run")  # port 9 (discard): nothing listens on loopback
    assert run.returncode == 2, run.stderr
    assert "no ROS master answers at http://127.0.0.1:9" in run.stderr
    assert "Will keep trying" not in run.stderr + run.stdout
