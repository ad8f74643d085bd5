"""Reading a ROS run's log (a rosbag :mod:`roboscript.ros.run_log` wrote) back: the goals the robot was sent, in
the model's joint order, and its joint states, as a :class:`~roboscript.run_record.RunRecord` for
:mod:`roboscript.replay`."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from roboscript.robot_config import RobotConfig, load_robot_config
from roboscript.ros.messages import message_class
from roboscript.ros.run_log import OUTCOME_TOPIC, RUN_TOPIC, TOOL_CALL_TOPIC, action_namespaces
from roboscript.run_record import Command, RunRecord
from roboscript.trajectory import JointTrajectory


def read_bag_log(path: str | Path, config: RobotConfig | str | Path | None = None) -> RunRecord:
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
