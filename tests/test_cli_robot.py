"""The command line's checks of a run on a running robot, before it connects to anything: which options need a
robot, and a configuration that drives its arm through another driver than the one asked for."""

from __future__ import annotations

import subprocess
import sys

import pytest

PROGRAM = "open_gripper()\n"


def _exec(tmp_path, *args: str) -> subprocess.CompletedProcess:
    program = tmp_path / "program.py"
    program.write_text(PROGRAM)
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(program), "--task", "simple_0", *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=300)


def test_robot_only_options_without_a_robot_say_how_to_name_one(tmp_path):
    run = _exec(tmp_path, "--dry-run")
    assert run.returncode == 2
    assert (
        "--dry-run applies only to a running robot: add --backend ros --master URI, or --backend franky "
        "--robot-config FILE" in run.stderr
    )
    run = _exec(tmp_path, "--dry-run", "--log-dir", str(tmp_path / "run"))
    assert run.returncode == 2 and "--dry-run, --log-dir apply only to a running robot" in run.stderr


@pytest.mark.parametrize(
    ("args", "said"),
    [
        (
            ["--backend", "franky", "--robot-config", "panda_franka_ros"],
            "drives its arm through ros (driver: ros), not franky: use --backend ros",
        ),
        (
            ["--backend", "ros", "--master", "http://127.0.0.1:9", "--robot-config", "fr3_franky"],
            "drives its arm through franky (driver: franky), not ros: use --backend franky",
        ),
        (["--backend", "franky", "--master", "http://127.0.0.1:9"], "--master names a ROS master: add --backend ros"),
    ],
)
def test_a_robot_named_the_wrong_way_is_refused_before_anything_connects(tmp_path, args, said):
    run = _exec(tmp_path, *args, "--dry-run")
    assert run.returncode == 2, run.stderr
    assert said in run.stderr
    assert "robot:" not in run.stdout  # refused before it connected to one
