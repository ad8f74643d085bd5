"""A run on a robot as its log holds it, decoded: what the robot was told (trajectories and gripper commands, in
the model's joint order) and where its arm was, on one clock that starts with the log.

Both logs decode to it: a ROS run's rosbag (:mod:`roboscript.ros.replay`) and a driver's JSON-lines log
(:mod:`roboscript.run_log`); :mod:`roboscript.replay` replays it on the simulated twin.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from roboscript.robot_config import RobotConfig
from roboscript.trajectory import JointTrajectory


@dataclass(frozen=True)
class Command:
    """One command the run sent: a trajectory (model joint order) or a gripper command (0 open .. 1 closed)."""

    time: float  # seconds since the log began
    kind: str  # "trajectory" or "gripper"
    trajectory: JointTrajectory | None = None
    closed: float = 0.0


@dataclass
class RunRecord:
    """What a run's log holds, decoded."""

    path: Path
    run: dict
    config: RobotConfig
    commands: list[Command]
    state_times: np.ndarray  # (N,) seconds since the log began
    states: np.ndarray  # (N, dof): the arm's joint positions, model order
    tool_calls: list[dict] = field(default_factory=list)
    outcome: dict | None = None

    def state_before(self, time: float) -> np.ndarray | None:
        """The last joint state logged before ``time``; ``None`` if none was."""
        index = int(np.searchsorted(self.state_times, time)) - 1
        return self.states[index] if index >= 0 else None
