"""The command line's robot commands: ``ros-sim`` (a simulated world served as a ROS robot), ``replay`` (a robot
run's log on the twin), and the side of ``exec`` and ``run`` that runs on a robot that is already running (with
``--backend ros --master URI``, or ``--backend franky --robot-config FILE``): its options, their checks, the
confirmation prompt, and the report."""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from roboscript.errors import InvalidArgumentError, UsageError

if TYPE_CHECKING:
    from roboscript.robot_config import RobotConfig

ROBOT_ONLY = ("dry_run", "validate_in_sim", "yes", "log_dir")


def add_robot_options(parser: argparse.ArgumentParser) -> None:
    group = parser.add_argument_group(
        "a robot that is already running (a real arm, or a ros-sim or franky-sim you started): --backend ros --master "
        "URI, or --backend franky --robot-config FILE (the file's franky.host is the arm's address)"
    )
    group.add_argument(
        "--master",
        default=None,
        metavar="URI",
        help="with --backend ros: drive the robot on this ROS master (http://HOST:PORT, or 'env' for "
        "$ROS_MASTER_URI) instead of serving the world on a master of each trial's own",
    )
    group.add_argument(
        "--dry-run",
        action="store_true",
        help="look, build the twin of the scene as perceived, run the program on it and write its planned "
        "trajectories and a video; send nothing to the robot",
    )
    group.add_argument(
        "--validate-in-sim",
        action="store_true",
        help="run the program on the twin of the scene first; send it to the robot only if it succeeded there",
    )
    group.add_argument("--yes", action="store_true", help="do not ask for confirmation before the first motion")
    group.add_argument(
        "--log-dir",
        default=None,
        help="where the run's log (run.bag on ROS, run.jsonl through franky) and the twin's files go; "
        "default out/robot/TIME",
    )


def robot_requested(args: argparse.Namespace) -> bool:
    """Whether the command is to drive a running robot: on ROS, ``--master`` names its master; through franky,
    ``--robot-config`` names the arm (a franky trial without one starts a franky-sim of its own). Refuses robot-only
    options otherwise."""
    franky_arm = args.backend == "franky" and getattr(args, "robot_config", None) is not None
    if getattr(args, "master", None) is None and not franky_arm:
        given = [f"--{name.replace('_', '-')}" for name in ROBOT_ONLY if getattr(args, name, None)]
        if given:
            raise UsageError(
                f"{', '.join(given)} {'applies' if len(given) == 1 else 'apply'} only to a running robot: add "
                "--backend ros --master URI, or "
                "--backend franky --robot-config FILE"
            )
        return False
    if getattr(args, "master", None) is not None and args.backend != "ros":
        raise UsageError("--master names a ROS master: add --backend ros")
    if args.video:
        raise UsageError("--video records a simulation; on a robot, --dry-run or --validate-in-sim film the twin")
    return True


def confirmation(args: argparse.Namespace) -> Callable[[str], bool]:
    """How the first motion is confirmed: not at all with ``--yes``, else by asking on the terminal; without one
    (a pipe, a CI job) the run is refused before it connects, rather than waiting for an answer that cannot come."""
    if args.yes or args.dry_run:
        return lambda question: True
    if not sys.stdin.isatty():
        raise UsageError(
            "the robot's first motion must be confirmed and there is no terminal to ask on: run it in a terminal, "
            "or pass --yes"
        )

    def ask(question: str) -> bool:
        return input(f"{question} [y/N] ").strip().lower() in ("y", "yes")

    return ask


def running_robot_config(args: argparse.Namespace) -> tuple[RobotConfig, str]:
    """The running robot's configuration, and where it is (a ROS master's URI, a Franka's address); refuses a
    configuration whose driver is not the ``--backend`` asked for."""
    from roboscript.robot_config import load_robot_config, ros_config_for

    config = load_robot_config(args.robot_config or ros_config_for(args.robot))
    if config.driver != args.backend:
        raise UsageError(
            f"the robot configuration {config.source or config.name} drives its arm through {config.driver} "
            f"(driver: {config.driver}), not {args.backend}: use --backend {config.driver}, or a configuration with "
            f"driver: {args.backend}"
        )
    if config.franky is not None:
        return config, config.franky.host
    uri = os.environ.get("ROS_MASTER_URI") if args.master == "env" else args.master
    if not uri:
        raise UsageError("--master env: ROS_MASTER_URI is not set")
    os.environ["ROS_MASTER_URI"] = uri
    return config, uri


def run_on_running_robot(args: argparse.Namespace, program: str, scene_ref: str) -> int:
    """Runs ``program`` on the running robot the options name, in the scene ``scene_ref`` describes; prints what
    happened."""
    from roboscript.robot_run import RobotRunPlan, log_path, run_on_robot
    from roboscript.sim.world_catalog import load_world

    confirm = confirmation(args)
    config, where = running_robot_config(args)
    out = Path(args.log_dir or Path("out/robot") / time.strftime("%Y%m%d-%H%M%S"))
    plan = RobotRunPlan(
        config,
        load_world(scene_ref),
        args.perception,
        out,
        dry_run=args.dry_run,
        validate_in_sim=args.validate_in_sim,
        timeout=args.timeout,
        seed=args.seed,
    )
    progress = (lambda line: None) if args.json else (lambda line: print(line, flush=True))
    progress(f"robot: {config.name} at {where}; log: {log_path(plan)}")
    result = run_on_robot(program, plan, confirm, progress)
    if args.json:
        print(json.dumps(result.to_dict()))
    else:
        if result.result is not None:
            print(f"robot: {result.result.outcome.value}" + (f": {result.result.error}" if result.result.error else ""))
        if result.stopped:
            print(result.stopped)
        if result.twin is not None:
            print("twin's files: " + ", ".join(str(f) for f in result.twin.files))
        replay = f" (replay it: roboscript replay {result.log} --world {scene_ref})" if result.sent else ""
        print(f"log: {result.log}{replay}")
    return 0 if result.ok else 1


def add_replay_command(sub) -> None:
    replay = sub.add_parser(
        "replay", help="replay a robot run's log (run.bag on ROS, run.jsonl through franky) on the simulated twin"
    )
    replay.add_argument("log", help="a run's log (run.bag or run.jsonl), as `exec` or `run` on a robot write it")
    replay.add_argument("--world", required=True, help="the twin's world: the scene's description (name or file)")
    replay.add_argument("--robot-config", default=None, help="default: the one the log names")
    replay.add_argument("--seed", type=int, default=0, help="with --randomize: the world's randomisation")
    replay.add_argument("--randomize", action="store_true", help="jitter the world's objects as a trial would")
    replay.add_argument("--video", default=None, help="record the replay into this MP4 file")
    replay.add_argument("--tolerance", type=float, default=0.05, help="radians: where twin and robot count as parted")
    replay.add_argument("--json", action="store_true", help="print one JSON object")
    replay.set_defaults(func=cmd_replay)


def cmd_replay(args: argparse.Namespace) -> int:
    from roboscript.replay import read_run_log, replay_on_twin, replay_report

    record = read_run_log(args.log, args.robot_config)
    steps = replay_on_twin(record, args.world, seed=args.seed, randomize=args.randomize, video=args.video)
    if args.json:
        print(
            json.dumps(
                {
                    "commands": len(steps),
                    "tool_calls": len(record.tool_calls),
                    "outcome": record.outcome,
                    "steps": [
                        {
                            "time": s.command.time,
                            "kind": s.command.kind,
                            "deviation": s.deviation,
                            "twin_error": s.twin_error,
                        }
                        for s in steps
                    ],
                }
            )
        )
    else:
        print(replay_report(record, steps, args.tolerance))
    return 0


def cmd_ros_sim(args: argparse.Namespace) -> int:
    from roboscript.robot_config import load_robot_config, ros_config_for
    from roboscript.sim.world_catalog import load_world

    robot = args.robot or load_world(args.world).robot
    config = load_robot_config(args.robot_config or ros_config_for(robot))
    if config.robot.name != robot:
        raise InvalidArgumentError(f"robot configuration {config.name} is for the {config.robot.name}, not the {robot}")
    if not os.environ.get("ROS_MASTER_URI"):
        raise InvalidArgumentError(
            "ROS_MASTER_URI is not set: start a master (rosmaster --core -p 11311) and export its URI"
        )
    try:
        from roboscript.rossim.server import serve
    except ImportError as exc:
        raise InvalidArgumentError(
            f"ros-sim needs ROS 1 (rospy, actionlib): see the README's ROS section ({exc})"
        ) from None
    task = None
    if args.task:
        from roboscript.bench.tasks import get_task

        task = get_task(args.task, args.suite)
    serve(args.world, robot, config, args.real_time_factor, args.camera_rate, args.seed, args.randomize, task=task)
    return 0


def add_ros_sim_command(sub) -> None:
    ros_sim = sub.add_parser("ros-sim", help="serve a simulated world as a ROS robot (the digital twin)")
    ros_sim.add_argument("world", help="a world name (see `roboscript worlds`) or a world file path")
    ros_sim.add_argument("--robot", choices=["panda", "ur5e"], default=None, help="default: the world's robot")
    ros_sim.add_argument(
        "--robot-config",
        default=None,
        help="the names to serve under: a robot configuration file or packaged name; default: panda_franka_ros "
        "or ur5e_ur_robot_driver",
    )
    ros_sim.add_argument(
        "--real-time-factor", type=float, default=1.0, help="simulated seconds per wall-clock second (default 1)"
    )
    ros_sim.add_argument("--camera-rate", type=float, default=1.0, help="camera images per simulated second")
    ros_sim.add_argument("--seed", type=int, default=0)
    ros_sim.add_argument("--randomize", action="store_true", help="jitter object poses (deterministic per seed)")
    ros_sim.add_argument(
        "--task", default=None, help="a task whose checks the twin evaluates when asked on /roboscript/evaluate"
    )
    ros_sim.add_argument("--suite", default="paper", help="the task's suite (default: paper)")
    ros_sim.set_defaults(func=cmd_ros_sim)
