"""One trial: build the task's world, run a program against the tool API, evaluate the task's checks.

:func:`run_trial` does it in the calling process; :mod:`roboscript.bench.runner` runs each trial in a child
process so that a crash or a hang in a program cannot take the runner down.
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field

from roboscript.bench.tasks import get_task
from roboscript.codegen.checker import check_program
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult, Limits, execute

MAX_OUTPUT = 4000  # characters of a program's printed output kept in its record


@dataclass(frozen=True)
class TrialSpec:
    """What to run: a program on a task's world with one robot and one seed.

    With ``llm`` (an LLM spec, see :func:`roboscript.llm.make_llm`) the program is generated in the trial from the
    task's query, and ``program`` is ignored.
    """

    task: str
    robot: str
    trial: int
    seed: int
    program: str
    timeout: float = 300.0
    video: str | None = None
    video_camera: str = "camera_left"
    memory_limit: int = 2 * 1024**3
    llm: str | None = None
    instruction: str | None = None  # asked of the LLM instead of the task's own instruction
    repair_rounds: int = 0  # rounds of feeding the checker's findings back to the LLM


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

    @property
    def passed(self) -> int:
        return sum(1 for c in self.checks if c["passed"])

    @property
    def success(self) -> bool:
        return bool(self.checks) and self.passed == len(self.checks)

    def to_dict(self) -> dict:
        return asdict(self)


def run_trial(spec: TrialSpec) -> TrialRecord:
    """Runs one trial in this process, the program in the sandbox (:mod:`roboscript.codegen.sandbox`)."""
    from roboscript.api import ToolAPI
    from roboscript.backends.mujoco_backend import MujocoBackend

    started = time.perf_counter()
    task = get_task(spec.task)
    backend = MujocoBackend(task.world, robot=spec.robot, seed=spec.seed, randomize=True)
    recorder = None
    try:
        checks = task.build_checks(backend.ground_truth)
        tools = ToolAPI.for_simulation(backend, seed=spec.seed)
        if spec.video:
            from roboscript.bench.video import VideoRecorder

            recorder = VideoRecorder(backend, spec.video, camera=spec.video_camera)
        sim_start = backend.time()
        program, exchanges, repairs = spec.program, [], 0
        if spec.llm is not None:
            query = task.query(backend.ground_truth, spec.instruction)
            program, exchanges, repairs, result = _generate(spec.llm, query, spec.repair_rounds)
        if program is not None:
            result = check_and_execute(program, tools.namespace(), Limits(spec.timeout, spec.memory_limit))
        backend.wait(1.0)  # let what was let go come to rest before judging
        results = [c.evaluate(backend.ground_truth).to_dict() for c in checks]
        outcome = result.outcome
        if outcome is Outcome.OK and not all(r["passed"] for r in results):
            outcome = Outcome.CHECKS_FAILED
        return TrialRecord(
            task=spec.task,
            robot=spec.robot,
            trial=spec.trial,
            seed=spec.seed,
            ok=result.error is None,
            error=result.error,
            checks=results,
            sim_time_s=round(backend.time() - sim_start, 3),
            wall_time_s=round(time.perf_counter() - started, 3),
            output=result.output[:MAX_OUTPUT],
            outcome=outcome.value,
            program=program if spec.llm is not None else None,
            llm_exchanges=exchanges,
            repairs=repairs,
        )
    finally:
        if recorder is not None:
            recorder.close()
        backend.close()


def check_and_execute(program: str, namespace: dict, limits: Limits) -> ExecutionResult:
    """The static checker first; only a program it passes runs."""
    findings = check_program(program)
    if findings:
        error = "; ".join(f"{f.message} (program line {f.line})" for f in findings[:5])
        return ExecutionResult(findings[0].outcome, error, "")
    return execute(program, namespace, limits)


def _generate(
    llm_spec: str, query: str, repair_rounds: int
) -> tuple[str | None, list[dict], int, ExecutionResult | None]:
    """The program an LLM writes for ``query`` (repaired against the checker for up to ``repair_rounds``), the
    exchanges behind it, the repair rounds used, and the result if there is no program."""
    from roboscript.codegen.agent import CodeAgent
    from roboscript.llm import LLMError, make_llm

    try:
        agent = CodeAgent(make_llm(llm_spec))
        generation = agent.write_program(query)
        agent.repair_static(query, generation, repair_rounds)
    except LLMError as exc:
        return None, [], 0, ExecutionResult(Outcome.LLM_ERROR, f"LLMError: {exc}", "")
    return generation.program, generation.exchanges, generation.repairs, None
