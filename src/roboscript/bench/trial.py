"""One trial: build the task's world, run a program against the tool API, evaluate the task's checks.

:func:`run_trial` does it in the calling process; :mod:`roboscript.bench.runner` runs each trial in a child
process so that a crash or a hang in a program cannot take the runner down.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path

from roboscript.bench.stored_programs import StoredProgram
from roboscript.bench.tasks import DEFAULT_SUITE, Task, free_task, get_task
from roboscript.bench.trial_world import TrialWorld, attempt_record
from roboscript.codegen.author import ProgramAuthor
from roboscript.codegen.execute import check_and_execute
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult, Limits
from roboscript.errors import InvalidArgumentError
from roboscript.llm import LLMError, make_llm
from roboscript.perception.modes import GROUND_TRUTH, PerceptionMode, perception_mode
from roboscript.phases import PhaseClock

BACKENDS = ("mujoco", "ros", "franky")


@dataclass(frozen=True)
class LLMAuthor:
    """A program the trial has an LLM write from the task's query: ``llm`` is an LLM spec (see
    :func:`roboscript.llm.make_llm`); ``repair_rounds``, rounds of feeding errors (checker, runtime, planning) back
    to it."""

    llm: str
    repair_rounds: int = 0

    def __post_init__(self) -> None:
        if self.repair_rounds < 0:
            raise InvalidArgumentError(f"repair rounds must be 0 or more, got {self.repair_rounds}")


@dataclass(frozen=True)
class TrialSpec:
    """What to run: a program on a task's world with one robot and one seed.

    ``program`` is where the program comes from, one value: its text (a :class:`StoredProgram` where it says where
    it came from), or an :class:`LLMAuthor`, which writes it in the trial from the task's query.
    """

    task: str
    robot: str
    trial: int
    seed: int
    program: str | StoredProgram | LLMAuthor
    timeout: float = 300.0
    video: str | None = None
    video_camera: str = "camera_left"
    memory_limit: int = 2 * 1024**3
    instruction: str | None = None  # asked of the LLM instead of the task's own instruction
    world: str | None = None  # a world name or file to run in without a task (no checks); ``task`` is then a label
    # Where the tools' knowledge comes from (roboscript.perception.modes); a name is parsed into a mode at once.
    perception: PerceptionMode | str = GROUND_TRUTH
    suite: str = DEFAULT_SUITE  # the suite ``task`` is of: a packaged suite's name or a suite file's path
    # mujoco; ros: the world served by ros-sim, the tools on the ROS backend; franky: the world served by franky-sim,
    # the tools driving its FR3 through libfranka
    backend: str = "mujoco"
    robot_config: str | None = None  # the ROS backend's robot configuration (default: the arm's packaged one)
    record: str | None = None  # an MCAP file to record the trial into (roboscript.record)

    def __post_init__(self) -> None:
        if not isinstance(self.program, str | StoredProgram | LLMAuthor):
            raise TypeError(f"a trial's program is its text, a StoredProgram or an LLMAuthor, got {self.program!r}")
        if self.timeout <= 0:
            raise InvalidArgumentError(f"the time limit must be positive, got {self.timeout} s")
        object.__setattr__(self, "perception", perception_mode(self.perception))
        if self.backend not in BACKENDS:
            raise InvalidArgumentError(f"unknown backend {self.backend!r}; backends: {', '.join(BACKENDS)}")

    @property
    def author(self) -> LLMAuthor | None:
        """The LLM that writes the program, if one does."""
        return self.program if isinstance(self.program, LLMAuthor) else None

    @property
    def program_text(self) -> str | None:
        """The program's text, where it is given (not written in the trial)."""
        if isinstance(self.program, StoredProgram):
            return self.program.program
        return None if isinstance(self.program, LLMAuthor) else self.program

    def attempts(self) -> int:
        """How many times the program may run: once, and once more after each repair round."""
        return 1 + (self.author.repair_rounds if self.author is not None else 0)


COULD_NOT_RUN = "the trial could not be run"  # how the record of a trial that never ran begins its error


@dataclass
class TrialRecord:
    """What happened: ``ok`` is true when the program ran to its end without an exception; ``outcome`` names the
    category (:class:`~roboscript.codegen.outcomes.Outcome`)."""

    task: str
    robot: str
    trial: int
    seed: int
    ok: bool
    error: str | None
    checks: list[dict] = field(default_factory=list)
    sim_time_s: float = 0.0
    wall_time_s: float = 0.0
    output: str = ""
    outcome: str = Outcome.OK.value
    program: str | None = None  # the generated program (LLM policies)
    repairs: int = 0  # repair rounds used
    llm_exchanges: list[dict] = field(default_factory=list)  # every prompt and raw response behind it
    attempts: list[dict] = field(default_factory=list)  # with repair: every run, first (unrepaired) to last
    program_source: str | None = None  # which stored program ran (a file, or an entry of a generated-code file)
    # Where the trial's wall time went, in seconds per phase (roboscript.phases), with "rest" and "wall".
    phases: dict[str, float] = field(default_factory=dict)
    # Which process judged the outcome and the checks, and where the program ran: never the same process.
    judged_by: str = ""
    node: str = ""  # the address of the Ray node that ran the trial; empty on a local process pool

    @property
    def never_ran(self) -> bool:
        """Whether the trial failed before its program could run (its world or its sandbox could not be set up,
        not the program's doing): a resumed run tries it again."""
        return not self.ok and not self.checks and (self.error or "").startswith(COULD_NOT_RUN)

    def first_attempt(self) -> TrialRecord:
        """The trial as it would have ended without repair: its first attempt (itself when there was one)."""
        if len(self.attempts) < 2:
            return self
        first = self.attempts[0]
        fields = ("ok", "error", "checks", "sim_time_s", "outcome", "program")
        return replace(self, **{k: first[k] for k in fields}, repairs=0, attempts=[])

    @property
    def passed(self) -> int:
        return sum(1 for c in self.checks if c["passed"])

    @property
    def success(self) -> bool:
        return bool(self.checks) and self.passed == len(self.checks)

    def to_dict(self) -> dict:
        return asdict(self)


def run_trial(
    spec: TrialSpec,
    announce: Callable[[float | None], None] | None = None,
    stage: Callable[[str], None] | None = None,
) -> TrialRecord:
    """Runs one trial in this process, the program in the sandbox (:mod:`roboscript.codegen.sandbox`).

    With an LLM and ``repair_rounds``, a program that the checker rejects, or that stops on an error or a planning
    failure, goes back to the LLM with the error, and the repaired program runs again in a freshly built world (the
    same seed, so the same world). Each run is an attempt in the record; the video shows the last one that ended
    (each attempt records into a file of its own, which replaces the video when the attempt is over).

    ``announce`` is told by when each program run must be over, and ``None`` after it (the watchdog of
    :mod:`roboscript.bench.workers`); ``stage``, what the trial is doing, in words (a command's progress).
    """
    stage = stage or _quiet
    clock = PhaseClock()
    task = free_task(spec.world, spec.instruction) if spec.world else get_task(spec.task, spec.suite)
    attempts: list[dict] = []
    author: ProgramAuthor | None = None
    failure: ExecutionResult | None = None  # the LLM could not be asked
    while True:
        stage("building the world" if not attempts else "building the world again for the repaired program")
        with _trial_world(spec, task) as world:
            if spec.author is not None and author is None and failure is None:
                stage(f"asking {spec.author.llm} for the program")
                query = task.query_for(spec.instruction)
                try:
                    author = ProgramAuthor(make_llm(spec.author.llm), query, world.backend.base_pose().position[:2])
                except LLMError as exc:
                    failure = ExecutionResult(Outcome.LLM_ERROR, f"LLMError: {exc}", "")
            program = spec.program_text if spec.author is None else (author.program if author else None)
            if program is None:
                result = failure
            else:
                limits = Limits(spec.timeout, spec.memory_limit).scaled_to_load()
                result = check_and_execute(program, world.namespace, limits, announce, stage)
            stage(_ended(result))
            stage("evaluating what it did")
            attempt = world.judge(result)
        attempt["program"] = program if spec.author is not None else None
        attempts.append(attempt)
        if author is None or len(attempts) >= spec.attempts():
            break
        if Outcome(attempt["outcome"]) not in REPAIRABLE:
            break
        stage(f"asking {spec.author.llm} to repair the program (round {len(attempts)} of {spec.author.repair_rounds})")
        try:
            author.repair(result)
        except LLMError as exc:
            attempt["repair_error"] = f"LLMError: {exc}"  # the LLM could not be asked; this attempt stands
            break
    last = attempts[-1]
    phases = clock.read()
    return TrialRecord(
        task=spec.task,
        robot=spec.robot,
        trial=spec.trial,
        seed=spec.seed,
        ok=last["ok"],
        error=last["error"],
        checks=last["checks"],
        sim_time_s=last["sim_time_s"],
        wall_time_s=round(phases["wall"], 3),
        output=last["output"],
        outcome=last["outcome"],
        program=last["program"],
        llm_exchanges=author.generation.exchanges if author else [],
        repairs=len(attempts) - 1,
        attempts=[{k: v for k, v in a.items() if k != "output"} for a in attempts]
        if len(attempts) > 1 or "repair_error" in last
        else [],
        program_source=spec.program.source if isinstance(spec.program, StoredProgram) else None,
        phases=phases,
        judged_by=last["judged_by"],
    )


def _quiet(what: str) -> None:
    pass


def _ended(result: ExecutionResult) -> str:
    """How a program run ended, in a few words."""
    if result.outcome is Outcome.OK:
        return "the program ended"
    first = (result.error or result.outcome.value).splitlines()[0][:160]
    if result.outcome is Outcome.LLM_ERROR:
        return f"no program was written: {first}"
    return f"the program stopped: {first}"


# What a repair round may answer: the checker's findings, errors while running, planning failures, time-outs.
REPAIRABLE = frozenset(
    {
        Outcome.SYNTAX,
        Outcome.UNKNOWN_FUNCTION,
        Outcome.BAD_ARGUMENTS,
        Outcome.FORBIDDEN_CONSTRUCT,
        Outcome.RUNTIME_ERROR,
        Outcome.PLANNING_FAILURE,
        Outcome.TIMEOUT,
    }
)


class SimTrialWorld(TrialWorld):
    """A task's world simulated here for one attempt: the backend, the tools, the checks, the video."""

    recorder = recording = None

    def build(self) -> None:
        from roboscript.assembly import build_tools
        from roboscript.backends.mujoco_backend import MujocoBackend

        spec = self.spec
        self.backend = MujocoBackend(self.task.world, robot=spec.robot, seed=spec.seed, randomize=True)
        self.ground_truth = self.backend.ground_truth
        self.checks = self.task.build_checks(self.ground_truth)
        tools = build_tools(self.backend, spec.perception, seed=spec.seed)
        self.namespace = tools.namespace()
        if spec.record:
            from roboscript.record.recording import TrialRecording

            self.recording = TrialRecording(self.backend, tools, _partial(spec.record))
            self.namespace = self.recording.wrap(self.namespace)
        if spec.video:
            from roboscript.bench.video import VideoRecorder

            self.recorder = VideoRecorder(self.backend, _partial(spec.video), camera=spec.video_camera)

    def judge(self, result: ExecutionResult) -> dict:
        """The attempt's outcome once what was let go has come to rest."""
        self.backend.wait(1.0)
        checks = [c.evaluate(self.ground_truth).to_dict() for c in self.checks]
        if self.recording is not None:
            self.recording.log_checks(checks)
        return attempt_record(result, checks, self.backend.time() - self.sim_start)

    def close(self, built: bool) -> None:
        # A world that was not built in full keeps no video and no recording: nothing of it ran.
        if built and self.recorder is not None:
            self.recorder.close()
            os.replace(self.recorder.path, self.spec.video)
        if built and self.recording is not None:
            self.recording.close()
            os.replace(self.recording.path, self.spec.record)
        if self.backend is not None:
            self.backend.close()


def _trial_world(spec: TrialSpec, task: Task):
    if spec.backend == "ros":
        from roboscript.bench.ros_trial import RosTrialWorld

        return RosTrialWorld(spec, task)
    if spec.backend == "franky":
        from roboscript.bench.franky_trial import FrankyTrialWorld

        return FrankyTrialWorld(spec, task)
    return SimTrialWorld(spec, task)


def _partial(video: str) -> str:
    """Where an attempt's video (or recording) is written until the attempt is over."""
    path = Path(video)
    return str(path.with_name(f"{path.stem}.partial{path.suffix}"))
