"""Replaying what a robot was told on its simulated twin.

The replay sends a run's logged trajectories and gripper commands in their order to a simulated twin of the robot
started where the logged robot started, and compares after each where the twin's arm ended with where the robot's
did (the last joint state logged before the next command). A run that failed on hardware shows there where the robot
and the twin parted: a goal the controller aborted, a grasp that closed on nothing, a collision.

Both logs replay: a ROS run's rosbag (``run.bag``) and a driver's JSON-lines log (``run.jsonl``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from roboscript.robot_config import RobotConfig
from roboscript.run_log import read_json_log
from roboscript.run_record import Command, RunRecord


def read_run_log(path: str | Path, config: RobotConfig | str | Path | None = None) -> RunRecord:
    """The run logged at ``path`` (a ``.bag`` or a ``.jsonl``); ``config`` overrides the robot configuration the log
    names."""
    path = Path(path)
    if path.suffix == ".jsonl":
        return read_json_log(path, config)
    if path.suffix == ".bag":
        from roboscript.ros.replay import read_bag_log  # ROS's Python packages: only for a ROS run's log

        return read_bag_log(path, config)
    raise ValueError(f"{path}: a run's log is run.bag (a ROS run) or run.jsonl (a run through franky)")


@dataclass(frozen=True)
class ReplayStep:
    """One command replayed: where the twin's arm ended, and how far from where the robot's did (radians)."""

    command: Command
    twin_error: str | None
    deviation: float | None


def replay_on_twin(record: RunRecord, world, seed: int = 0, randomize: bool = False, video: str | None = None):
    """Replays ``record``'s commands on a twin of ``world`` (a world name, file or :class:`WorldSpec`) with the
    logged robot, started at the first logged joint state; a list of :class:`ReplayStep`."""
    from roboscript.backends.mujoco_backend import MujocoBackend

    if not record.commands:  # a dry run, a run stopped before its first motion: nothing to replay
        return []
    backend = MujocoBackend(world, record.config.robot.name, seed=seed, randomize=randomize, start=record.states[0])
    recorder = None
    if video:
        from roboscript.bench.video import VideoRecorder

        recorder = VideoRecorder(backend, video)
    steps = []
    try:
        following = [c.time for c in record.commands[1:]] + [record.state_times[-1] + 1.0]
        for command, until in zip(record.commands, following, strict=True):
            error = None
            try:
                if command.kind == "trajectory":
                    backend.execute_trajectory(command.trajectory)
                else:
                    backend.set_gripper(command.closed)
            except Exception as exc:  # the twin's own failure is part of the report, not the end of it
                error = f"{type(exc).__name__}: {exc}"
            robot = record.state_before(until)
            deviation = None if robot is None else float(np.max(np.abs(backend.joint_positions() - robot)))
            steps.append(ReplayStep(command, error, deviation))
    finally:
        if recorder is not None:
            recorder.close()
        backend.close()
    return steps


def replay_report(record: RunRecord, steps: list[ReplayStep], tolerance: float = 0.05) -> str:
    """The replay as text: a line a command, the ones where the twin and the robot parted marked."""
    outcome = json.dumps(record.outcome) if record.outcome else "none logged"
    lines = [
        f"{record.path}: {record.config.name} ({record.config.robot.name}), {len(record.commands)} commands, "
        f"{len(record.tool_calls)} tool calls; outcome: {outcome}"
    ]
    for i, step in enumerate(steps, 1):
        c = step.command
        what = f"trajectory {c.trajectory.duration:.2f} s" if c.kind == "trajectory" else f"gripper {c.closed:.2f}"
        gap = "n/a" if step.deviation is None else f"{step.deviation:.4f} rad"
        mark = "  <- parted" if step.deviation is not None and step.deviation > tolerance else ""
        error = f"  twin: {step.twin_error}" if step.twin_error else ""
        lines.append(f"  {i:3d}. t={c.time:7.2f} s  {what:<22} twin vs robot {gap}{mark}{error}")
    return "\n".join(lines)
