"""A run's JSON-lines log (what a run through a driver of the project's own leaves) and its replay on the twin: the
commands a backend was sent, where its arm went, the tool calls, written as they happen and read back."""

from __future__ import annotations

import json

import numpy as np
import pytest

from helpers import min_jerk_through
from roboscript.backends.logged import LoggedBackend
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.replay import read_run_log, replay_on_twin, replay_report
from roboscript.run_log import JsonRunLog, logged_namespace, read_json_log

WORLD = "world_2_pick_and_place"


def _move(backend, delta) -> None:
    start = backend.joint_positions()
    robot = backend.robot
    backend.execute_trajectory(
        min_jerk_through(
            np.array([start, start + delta]), np.array(robot.max_velocity), np.array(robot.max_acceleration), 0.5
        )
    )


@pytest.fixture
def logged_run(tmp_path):
    """A short run on the simulated Panda, logged: two motions and a gripper command, two tool calls."""
    path = tmp_path / "run.jsonl"
    with MujocoBackend(WORLD, robot="panda") as robot, JsonRunLog(path) as log:
        backend = LoggedBackend(robot, log.backend_event)
        log.run({"robot_config": "panda_franka_ros", "scene": WORLD, "program": "..."})
        tools = logged_namespace({"move": lambda d: _move(backend, np.array(d)), "fail": lambda: 1 / 0}, log)
        tools["move"]([0.3, 0, 0, -0.2, 0, 0, 0])
        backend.set_gripper(1.0)
        with pytest.raises(ZeroDivisionError):
            tools["fail"]()
        _move(backend, np.array([-0.3, 0, 0, 0.2, 0, 0, 0]))
        log.outcome({"outcome": "ok"})
        ends = backend.joint_positions()
    return path, ends


def test_the_log_holds_each_command_where_the_arm_went_and_each_tool_call(logged_run):
    path, ends = logged_run
    record = read_json_log(path)
    assert [c.kind for c in record.commands] == ["trajectory", "gripper", "trajectory"]
    assert record.commands[1].closed == 1.0
    assert len(record.states) == 4  # before the first command and after each
    assert np.allclose(record.states[-1], ends)
    assert record.commands[0].trajectory.positions.shape[1] == 7
    assert [c["tool"] for c in record.tool_calls] == ["move", "fail"]
    assert "ZeroDivisionError" in record.tool_calls[1]["error"]
    assert record.outcome == {"outcome": "ok"} and record.config.robot.name == "panda"


def test_the_logged_commands_replay_on_the_twin_to_where_the_arm_went(logged_run):
    path, _ = logged_run
    record = read_run_log(path)
    steps = replay_on_twin(record, WORLD)
    assert len(steps) == 3 and all(s.twin_error is None for s in steps)
    assert max(s.deviation for s in steps) < 0.01
    assert "3 commands, 2 tool calls" in replay_report(record, steps)


def test_a_log_without_commands_replays_as_nothing(tmp_path):
    path = tmp_path / "run.jsonl"
    with JsonRunLog(path) as log:
        log.run({"robot_config": "panda_franka_ros", "scene": WORLD, "dry_run": True})
        log.outcome({"outcome": None, "stopped": "dry run"})
    record = read_run_log(path)
    assert record.commands == [] and record.states.shape == (0, 7)
    assert replay_on_twin(record, WORLD) == []


def test_a_tool_call_the_log_cannot_take_leaves_the_program_as_the_tool_left_it(tmp_path, caplog):
    class FullDisk(JsonRunLog):
        """Test double of a log on a full disk."""

        def tool_call(self, *args, **kwargs):
            raise OSError(28, "No space left on device")

    with FullDisk(tmp_path / "run.jsonl") as log:
        tools = logged_namespace({"answer": lambda: {1: "numbers as keys"}}, log)
        assert tools["answer"]() == {1: "numbers as keys"}
    assert "did not take a call of answer" in caplog.text
    with JsonRunLog(tmp_path / "keys.jsonl") as log:
        logged_namespace({"answer": lambda: {np.int64(1): "numbers as keys"}}, log)["answer"]()
    event = json.loads((tmp_path / "keys.jsonl").read_text())
    assert event["answer"] == {"1": "numbers as keys"}


def test_a_log_cut_short_mid_line_reads_up_to_its_last_whole_event(logged_run):
    path, _ = logged_run
    text = path.read_text()
    path.write_text(text[: text.rindex('{"t"') + 12])  # killed while writing the outcome
    record = read_json_log(path)
    assert record.outcome is None and len(record.commands) == 3


def test_a_damaged_log_names_the_line_and_a_log_of_another_kind_is_refused(tmp_path, logged_run):
    path, _ = logged_run
    lines = path.read_text().splitlines()
    lines[2] = "garbage"
    damaged = tmp_path / "damaged.jsonl"
    damaged.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"damaged\.jsonl:3: not a JSON event"):
        read_json_log(damaged)
    with pytest.raises(ValueError, match=r"run\.bag \(a ROS run\) or run\.jsonl"):
        read_run_log(tmp_path / "run.txt")
    no_run = tmp_path / "no_run.jsonl"
    no_run.write_text(json.dumps({"t": 0, "kind": "state", "joint_names": [], "positions": []}) + "\n")
    with pytest.raises(ValueError, match="no 'run' event"):
        read_json_log(no_run)


def test_a_state_and_the_next_command_logged_within_one_tick_pair_in_the_order_written(logged_run):
    # On a fast machine the state after the first motion and the gripper command after it share a stamp (the log's
    # clock ticks in 0.1 ms): the replay then took the state before the motion for the one after it, 0.3 rad off.
    path, _ = logged_run
    events = [json.loads(line) for line in path.read_text().splitlines()]
    kinds = [e["kind"] for e in events]
    gripper = kinds.index("gripper")
    after_motion = max(k for k in range(gripper) if kinds[k] == "state")
    for event in events[after_motion:gripper]:  # the state after the motion (and what followed), in the same tick
        event["t"] = events[gripper]["t"]
    path.write_text("\n".join(json.dumps(e) for e in events) + "\n")
    record = read_run_log(path)
    assert record.state_times[1] < record.commands[1].time  # written first, so logged first
    steps = replay_on_twin(record, WORLD)
    assert max(s.deviation for s in steps) < 0.01
