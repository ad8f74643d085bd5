"""A program on a Franka that is already running, from the command line, as a lab runs one on its FR3:
``roboscript exec --backend franky --robot-config lab.yaml`` with ``--dry-run`` and ``--validate-in-sim``, its log
(``run.jsonl``), and ``roboscript replay`` of that log on the twin.

The arm is franky-sim on loopback (libfranka's protocol on both ends); the cameras are RealSense recordings of the
same world, written by librealsense's own recorder and played back through the RealSense driver, as a lab's
configuration names its cameras. Nothing of the simulator reaches the program: the checks read franky-sim's world
on the test's side."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

pytest.importorskip("franky", reason="the franky extra is not installed (make test installs it)")
pytest.importorskip("franky_sim", reason="the franky extra is not installed (make test installs it)")
pytest.importorskip("pyrealsense2", reason="the realsense extra is not installed (make test installs it)")

import yaml

from realsense_recordings import record_d400
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.franky_trial import FRANKY_SIM_SPEED_SCALE
from roboscript.frankysim.launch import FrankySim
from roboscript.frankysim.mirror import WorldMirror
from roboscript.robot_config import config_path
from roboscript.robots import get_robot
from roboscript.sim.world_catalog import load_world

WORLD = "world_2_pick_and_place"
SHOTS = 6  # frames a camera's recording holds: each look takes one
PICK = """\
detect_objects(object_list=['apple'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='apple', description='center'))
close_gripper()
attach_object('apple')
move_in_direction([0, 0, 1], 0.1)
"""
MISSES = """\
detect_objects(object_list=['apple'])
open_gripper()
grasp(parse_central_lift_grasp_pose(object_name='banana', description='center'))
"""  # there is no banana: it fails on the twin, after a gripper command the arm must never get


def _recorded_cameras(folder) -> list[dict]:
    """The world's cameras as RealSense entries of a configuration, each with a recording of what it sees with
    the arm at home (where franky-sim starts it)."""
    entries = []
    with MujocoBackend(WORLD, robot="fr3", settle=0.2) as backend:
        for number, name in enumerate(backend.camera_names()):
            frame = backend.capture(name)
            serial = f"81761207{number:04d}"
            path = folder / f"{name}.db3"
            record_d400(path, serial, [(frame, frame.depth, frame.intrinsics)] * SHOTS)
            x, y, z, w = frame.extrinsics.quaternion
            entries.append(
                {
                    "name": name,
                    "realsense": {
                        "serial": serial,
                        "recording": path.name,
                        "position": frame.extrinsics.position.tolist(),
                        "quaternion": [float(w), float(x), float(y), float(z)],
                    },
                }
            )
    return entries


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A franky-sim serving the world, and a lab's configuration of it (franky-sim's address, the recorded
    RealSense cameras)."""
    folder = tmp_path_factory.mktemp("lab")
    data = yaml.safe_load(config_path("fr3_franky").read_text())
    data["name"] = "lab_fr3"
    data["franky"].update(realtime="ignore")
    data["safety"]["speed_scale"] = FRANKY_SIM_SPEED_SCALE  # franky-sim lags less, slower
    data["cameras"] = _recorded_cameras(folder)
    with FrankySim(world=WORLD) as sim:
        data["franky"]["host"] = sim.host
        config = folder / "lab.yaml"
        config.write_text(yaml.safe_dump(data))
        yield sim, config


def _roboscript(*args: str, timeout: float = 900) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "roboscript.cli", *args], capture_output=True, text=True, timeout=timeout
    )


def _exec(lab, tmp_path, *flags: str, program: str = PICK) -> tuple[dict, subprocess.CompletedProcess]:
    _, config = lab
    written = tmp_path / "program.py"
    written.write_text(program)
    run = _roboscript(
        "exec", str(written), "--backend", "franky", "--robot-config", str(config), "--world", WORLD,
        "--log-dir", str(tmp_path / "run"), "--json", *flags,
    )  # fmt: skip
    lines = run.stdout.strip().splitlines()
    assert lines, run.stderr[-3000:]
    return json.loads(lines[-1]), run


def _apple_height(sim: FrankySim) -> float:
    mirror = WorldMirror(sim, load_world(WORLD))
    mirror.sync()
    return float(mirror.ground_truth.pose("apple").position[2])


def test_a_dry_run_plans_on_the_twin_of_what_the_cameras_see_and_moves_nothing(lab, tmp_path):
    sim, _ = lab
    before, _ = sim.state()
    result, run = _exec(lab, tmp_path, "--dry-run")
    assert run.returncode == 0, run.stderr[-3000:]
    assert result["ok"] and not result["sent"] and result["stopped"].startswith("dry run")
    assert result["twin"]["outcome"] == "ok" and result["twin"]["commands"] >= 4
    assert "apple" in result["twin"]["scene"]
    plan = json.loads((tmp_path / "run" / "twin" / "plan.json").read_text())
    assert [c["kind"] for c in plan["commands"]].count("trajectory") >= 2
    after, _ = sim.state()
    assert np.allclose(after, before, atol=2e-3)  # nothing was sent: the arm and the apple stand where they stood
    kinds = [json.loads(line)["kind"] for line in (tmp_path / "run" / "run.jsonl").read_text().splitlines()]
    assert kinds == ["run", "state", "note", "outcome"]  # the twin's run is noted; nothing reached the arm


def test_a_program_that_fails_on_the_twin_is_not_sent(lab, tmp_path):
    sim, _ = lab
    before, _ = sim.state()
    result, run = _exec(lab, tmp_path, "--validate-in-sim", "--yes", program=MISSES)
    assert run.returncode == 1, run.stderr[-3000:]
    assert not result["ok"] and not result["sent"] and result["stopped"].startswith("not sent: the program failed")
    assert result["twin"]["outcome"] != "ok"
    after, _ = sim.state()
    assert np.allclose(after, before, atol=2e-3)
    kinds = [json.loads(line)["kind"] for line in (tmp_path / "run" / "run.jsonl").read_text().splitlines()]
    assert "trajectory" not in kinds and "gripper" not in kinds and "tool_call" not in kinds


def test_a_validated_run_picks_the_apple_through_libfranka_and_its_log_replays_on_the_twin(lab, tmp_path):
    sim, _ = lab
    resting = _apple_height(sim)
    result, run = _exec(lab, tmp_path, "--validate-in-sim", "--yes")
    assert run.returncode == 0, (run.stdout[-3000:], run.stderr[-3000:])
    assert result["ok"] and result["sent"] and result["outcome"] == "ok" and result["twin"]["outcome"] == "ok"
    assert _apple_height(sim) > resting + 0.05  # in franky-sim's world, the apple is in the hand, lifted

    log = tmp_path / "run" / "run.jsonl"
    events = [json.loads(line) for line in log.read_text().splitlines()]
    tools = [e["tool"] for e in events if e["kind"] == "tool_call"]
    assert tools[:3] == ["detect_objects", "open_gripper", "parse_central_lift_grasp_pose"]
    assert "close_gripper" in tools and tools[-1] == "move_in_direction"
    assert events[-1]["kind"] == "outcome" and events[-1]["outcome"]["outcome"] == "ok"

    replay = _roboscript("replay", str(log), "--world", WORLD, "--json", timeout=300)
    assert replay.returncode == 0, replay.stderr[-3000:]
    replayed = json.loads(replay.stdout)
    assert replayed["tool_calls"] == len(tools) and replayed["commands"] >= 4
    deviations = [s["deviation"] for s in replayed["steps"] if s["deviation"] is not None]
    assert deviations and max(deviations) < 0.05  # the twin follows where franky-sim's arm went
    home = get_robot("fr3").home
    first = next(e for e in events if e["kind"] == "state")
    assert events[0]["kind"] == "run" and np.allclose(first["positions"], home, atol=0.02)
