"""Reading a run's log (:mod:`roboscript.ros.run_log`) back, and replaying what the robot was told on the twin.

The replay sends the logged goals, trajectories and gripper commands in their order, to a simulated twin of the
robot started where the logged robot started, and compares after each where the twin's arm ended with where the
robot's did (the last joint state logged before the next command). A run that failed on hardware shows there where
the robot and the twin parted: a goal the controller aborted, a grasp that closed on nothing, a collision.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from roboscript.robot_config import RobotConfig, load_robot_config
from roboscript.ros.messages import message_class
from roboscript.ros.run_log import OUTCOME_TOPIC, RUN_TOPIC, TOOL_CALL_TOPIC, action_namespaces
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
    """What a run's bag holds, decoded."""

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


def read_run_log(path: str | Path, config: RobotConfig | str | Path | None = None) -> RunRecord:
    """The run logged at ``path``; ``config`` overrides the robot configuration the log names."""
    import rosbag

    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"no run log at {path}")
    with rosbag.Bag(str(path)) as bag:
        start = bag.get_start_time()
        run = _json_messages(bag, RUN_TOPIC)
        if not run:
            raise ValueError(f"{path} has no {RUN_TOPIC} message: it is not a RoboScript run's log")
        described = run[0][1]
        config = _config(config if config is not None else described["robot_config"])
        commands = _commands(bag, config, start)
        state_times, states = _states(bag, config, start)
        calls = [c for _, c in _json_messages(bag, TOOL_CALL_TOPIC)]
        outcome = _json_messages(bag, OUTCOME_TOPIC)
    return RunRecord(path, described, config, commands, state_times, states, calls, outcome[-1][1] if outcome else None)


def _config(reference: RobotConfig | str | Path) -> RobotConfig:
    return reference if isinstance(reference, RobotConfig) else load_robot_config(reference)


def _json_messages(bag, topic: str) -> list[tuple[float, dict]]:
    return [(t.to_sec(), json.loads(m.data)) for _, m, t in bag.read_messages(topics=[topic])]


def _raw(bag, topic: str, type_name: str):
    """``(time, message)`` of an action goal topic. The time is the goal's own stamp, set by the sender when it
    sent it: the bag's time is when the log's node heard it, which on a busy machine is after the robot started."""
    cls = message_class(type_name)
    for _, (_, data, _, _, _), t in bag.read_messages(topics=[topic], raw=True):
        message = cls().deserialize(data)
        sent = message.header.stamp.to_sec()
        yield (sent if sent > 0 else t.to_sec()), message


def _commands(bag, config: RobotConfig, start: float) -> list[Command]:
    trajectory_ns, *hands = action_namespaces(config)
    order = [config.driver_joint(j) for j in config.robot.arm_joints]
    commands = []
    for t, goal in _raw(bag, f"{trajectory_ns}/goal", "control_msgs/FollowJointTrajectoryActionGoal"):
        sent = goal.goal.trajectory
        columns = [list(sent.joint_names).index(name) for name in order]
        points = sent.points
        commands.append(
            Command(
                t - start,
                "trajectory",
                JointTrajectory(
                    np.array([p.time_from_start.to_sec() for p in points]),
                    np.array([[p.positions[c] for c in columns] for p in points]),
                    np.array([[p.velocities[c] if p.velocities else 0.0 for c in columns] for p in points]),
                ),
            )
        )
    gripper = config.gripper
    span = gripper.closed_position - gripper.open_position
    if gripper.kind == "franka":
        kinds = {hands[0]: "franka_gripper/MoveActionGoal", hands[1]: "franka_gripper/GraspActionGoal"}
        for ns, type_name in kinds.items():
            for t, goal in _raw(bag, f"{ns}/goal", type_name):
                closed = (goal.goal.width - gripper.open_position) / span
                commands.append(Command(t - start, "gripper", closed=float(np.clip(closed, 0, 1)) + 0.0))
    else:
        for t, goal in _raw(bag, f"{hands[0]}/goal", "control_msgs/GripperCommandActionGoal"):
            closed = (goal.goal.command.position - gripper.open_position) / span
            commands.append(Command(t - start, "gripper", closed=float(np.clip(closed, 0, 1)) + 0.0))
    return sorted(commands, key=lambda c: c.time)


def _states(bag, config: RobotConfig, start: float) -> tuple[np.ndarray, np.ndarray]:
    order = [config.driver_joint(j) for j in config.robot.arm_joints]
    times, states = [], []
    for _, message, t in bag.read_messages(topics=[config.joint_states]):
        named = dict(zip(message.name, message.position, strict=False))
        if all(n in named for n in order):
            times.append(t.to_sec() - start)
            states.append([named[n] for n in order])
    if not states:
        raise ValueError(f"the log holds no joint states of the arm on {config.joint_states}")
    return np.array(times), np.array(states)


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
