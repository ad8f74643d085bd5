"""A program on a robot that is already running (a real arm; a `roboscript ros-sim` or a franky-sim someone started):
sim-first, logged, and confirmed before the first motion.

The run, in order:

1. connect to the robot the configuration describes, through its driver (ROS, or libfranka with franky), and start
   its log: a rosbag ``run.bag`` on ROS (:mod:`roboscript.ros.run_log`), a JSON-lines ``run.jsonl`` through franky
   (:mod:`roboscript.run_log`); ``roboscript replay`` reads both;
2. build the tools on it, perception from its cameras, the scene's description naming what to look for;
3. with ``dry_run`` or ``validate_in_sim``: look, build the twin of the scene as perceived (:mod:`roboscript.twin`),
   the twin's arm where the robot's is, and run the program on the twin, writing the trajectories it planned and a
   video of the twin executing them. A dry run ends there, having sent nothing. A validation that failed ends there
   too: the program is not sent;
4. ask for confirmation (unless given beforehand), then run the program on the robot, each tool call logged.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

from roboscript.backends.base import Backend
from roboscript.backends.logged import LoggedBackend
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult, Limits
from roboscript.errors import UsageError
from roboscript.perception.modes import GROUND_TRUTH, PerceptionMode
from roboscript.robot_config import RobotConfig
from roboscript.run_log import JsonRunLog, RunLog, logged_namespace
from roboscript.sim.world_file import WorldSpec
from roboscript.twin import Twin, perceived_twin

TWIN_TOPIC = "/roboscript/twin"


@dataclass(frozen=True)
class RobotRunPlan:
    """What to run on which robot, and how carefully.

    ``scene``: the description of what is in front of the robot (a world file: its furniture, and the objects to
    look for); ``out``: where the log and the twin's files go."""

    config: RobotConfig
    scene: WorldSpec
    perception: PerceptionMode
    out: Path
    dry_run: bool = False
    validate_in_sim: bool = False
    timeout: float = 300.0
    seed: int = 0
    video: bool = True


@dataclass
class TwinRun:
    """The program's run on the twin: its result, the commands it sent, and the files written."""

    twin: Twin
    result: ExecutionResult
    commands: list[dict]
    files: list[Path] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.result.outcome == Outcome.OK


@dataclass
class RobotRunResult:
    """How a run on the robot went. ``result`` is the robot's run; ``None`` where nothing was sent (a dry run, a
    failed validation, a refused confirmation: ``stopped`` says which) or the run was cut short (``interrupted``
    says by what; ``sent`` whether the program had begun on the robot)."""

    program: str
    log: Path
    twin: TwinRun | None = None
    result: ExecutionResult | None = None
    stopped: str | None = None
    sent: bool = False  # the program began to run on the robot
    interrupted: str | None = None  # what ended the run before it could finish (Ctrl-C, a lost connection)

    @property
    def ok(self) -> bool:
        if self.interrupted is not None:
            return False
        if self.result is not None:
            return self.result.outcome == Outcome.OK
        return (
            self.stopped is not None and self.stopped.startswith("dry run") and self.twin is not None and self.twin.ok
        )

    def to_dict(self) -> dict:
        return {
            "ok": self.ok,
            "sent": self.sent,
            "stopped": self.stopped,
            "outcome": self.result.outcome.value if self.result else None,
            "error": self.result.error if self.result else self.interrupted,
            "twin": None
            if self.twin is None
            else {
                "outcome": self.twin.result.outcome.value,
                "error": self.twin.result.error,
                "commands": len(self.twin.commands),
                "scene": self.twin.twin.summary(),
                "files": [str(f) for f in self.twin.files],
            },
            "log": str(self.log),
        }


def log_path(plan: RobotRunPlan) -> Path:
    """Where a run's log goes: ``run.bag`` on ROS, ``run.jsonl`` through a driver of the project's own."""
    return plan.out / ("run.bag" if plan.config.driver == "ros" else "run.jsonl")


@contextmanager
def connected(plan: RobotRunPlan, description: dict) -> Iterator[tuple[Backend, RunLog]]:
    """The robot ``plan`` names, through its configuration's driver, and the run's log, begun with ``description``
    and open until the block ends (on ROS, the master is the one ``ROS_MASTER_URI`` names)."""
    path = log_path(plan)
    if plan.config.driver == "franky":
        from roboscript.backends.franky import franky_backend

        with franky_backend(plan.config) as robot, JsonRunLog(path) as log:
            log.run(description)
            yield LoggedBackend(robot, log.backend_event), log
        return
    from roboscript.backends.ros import ros_backend
    from roboscript.ros.run_log import RosRunLog

    with ros_backend(plan.config) as robot, RosRunLog(plan.config, path) as log:
        log.run(description)
        yield robot, log  # the bag records the commands as the robot's action servers hear them


def _description(program: str, plan: RobotRunPlan) -> dict:
    source = plan.config.source
    return {
        # a file by its whole path, so that the log replays from anywhere; a packaged configuration by its name
        "robot_config": str(Path(source).resolve())
        if source and Path(source).is_file()
        else source or plan.config.name,
        "robot": plan.config.robot.name,
        "scene": plan.scene.source,
        "perception": str(plan.perception),
        "dry_run": plan.dry_run,
        "validate_in_sim": plan.validate_in_sim,
        "program": program,
        "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
    }


def run_on_robot(
    program: str,
    plan: RobotRunPlan,
    confirm: Callable[[str], bool],
    progress: Callable[[str], None] = print,
) -> RobotRunResult:
    """Runs ``program`` on the robot ``plan`` describes.

    ``confirm(question)`` is asked once, before anything is sent to the robot; answering no ends the run."""
    from roboscript.assembly import build_tools
    from roboscript.codegen.execute import check_and_execute

    if log_path(plan).exists():
        raise UsageError(f"a run's log is already at {log_path(plan)}: give each run a folder of its own (--log-dir)")
    plan.out.mkdir(parents=True, exist_ok=True)
    outcome = RobotRunResult(program, log_path(plan))
    with connected(plan, _description(program, plan)) as (robot, log):
        tools = build_tools(robot, plan.perception, seed=plan.seed, scene=plan.scene)
        try:
            if plan.dry_run or plan.validate_in_sim:
                progress("looking at the scene to build its twin")
                twin = perceived_twin(plan.scene, tools.perception)
                progress(twin.summary())
                outcome.twin = run_on_twin(program, twin, robot.joint_positions(), plan, progress)
                log.note(TWIN_TOPIC, outcome.to_dict()["twin"])
                if plan.dry_run:
                    outcome.stopped = "dry run: the program ran on the twin; nothing was sent to the robot"
                    return outcome
                if not outcome.twin.ok:
                    outcome.stopped = (
                        f"not sent: the program failed on the twin ({outcome.twin.result.outcome.value}: "
                        f"{outcome.twin.result.error})"
                    )
                    return outcome
            question = f"run the program on the {plan.config.robot.name} ({plan.config.name})?"
            if not confirm(question):
                outcome.stopped = "not sent: the run was not confirmed"
                return outcome
            progress("running the program on the robot")
            outcome.sent = True
            outcome.result = check_and_execute(
                program, logged_namespace(tools.namespace(), log), Limits(plan.timeout).scaled_to_load()
            )
            return outcome
        except BaseException as exc:  # an interruption, a lost robot: the log says how the run ended, then it goes on
            outcome.interrupted = f"{type(exc).__name__}: {exc}"
            raise
        finally:
            log.outcome(outcome.to_dict())


def run_on_twin(
    program: str, twin: Twin, start, plan: RobotRunPlan, progress: Callable[[str], None] = print
) -> TwinRun:
    """Runs ``program`` on ``twin`` (its arm at ``start``) with tools on its ground truth (the scene as perceived);
    writes ``twin/plan.json`` (every trajectory and gripper command) and, with ``plan.video``, ``twin/twin.mp4``."""
    from roboscript.assembly import build_tools
    from roboscript.codegen.execute import check_and_execute

    folder = plan.out / "twin"
    folder.mkdir(parents=True, exist_ok=True)
    backend = LoggedBackend(MujocoBackend(twin.world, plan.config.robot.name, start=start))
    recorder, files = None, []
    try:
        if plan.video:
            recorder = _recorder(backend, folder / "twin.mp4", progress)
        tools = build_tools(backend, GROUND_TRUTH, seed=plan.seed)
        progress("running the program on the twin")
        result = check_and_execute(program, tools.namespace(), Limits(plan.timeout).scaled_to_load())
        backend.wait(0.5)
    finally:
        if recorder is not None:
            recorder.close()
            files.append(recorder.path)
        backend.close()
    plan_file = folder / "plan.json"
    plan_file.write_text(
        json.dumps(
            {
                "robot": plan.config.robot.name,
                "scene": twin.summary(),
                "outcome": result.outcome.value,
                "error": result.error,
                "commands": backend.commands,
            },
            indent=1,
        )
    )
    progress(f"twin: {result.outcome.value}" + (f": {result.error}" if result.error else ""))
    return TwinRun(twin, result, backend.commands, [plan_file, *files])


def _recorder(backend, path: Path, progress: Callable[[str], None]):
    from roboscript.bench.video import VideoRecorder

    try:
        return VideoRecorder(backend, path)
    except RuntimeError as exc:  # no video encoder installed: the plan is still written
        progress(f"no video of the twin: {exc}")
        return None
