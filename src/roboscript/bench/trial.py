"""One trial: build the task's world, run a program against the tool API, evaluate the task's checks.

:func:`run_trial` does it in the calling process; :mod:`roboscript.bench.runner` runs each trial in a child
process so that a crash or a hang in a program cannot take the runner down.
"""

from __future__ import annotations

import io
import signal
import time
import traceback
from dataclasses import asdict, dataclass, field

from roboscript.bench.tasks import get_task

PROGRAM_FILENAME = "<program>"
MAX_OUTPUT = 4000  # characters of a program's printed output kept in its record


class ProgramTimeout(BaseException):  # not an Exception, so that a program's ``except Exception`` cannot hide it
    """The program ran past its time limit."""


@dataclass(frozen=True)
class TrialSpec:
    """What to run: a program on a task's world with one robot and one seed."""

    task: str
    robot: str
    trial: int
    seed: int
    program: str
    timeout: float = 300.0
    video: str | None = None
    video_camera: str = "camera_left"


@dataclass
class TrialRecord:
    """What happened: ``ok`` is true when the program ran to its end without an exception."""

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

    @property
    def passed(self) -> int:
        return sum(1 for c in self.checks if c["passed"])

    @property
    def success(self) -> bool:
        return bool(self.checks) and self.passed == len(self.checks)

    def to_dict(self) -> dict:
        return asdict(self)


def describe_exception(exc: BaseException) -> str:
    """``Type: message (program line N)``, the line being the deepest one in the program itself."""
    line = None
    for frame in traceback.extract_tb(exc.__traceback__):
        if frame.filename == PROGRAM_FILENAME:
            line = frame.lineno
    if isinstance(exc, SyntaxError) and exc.filename == PROGRAM_FILENAME:
        line = exc.lineno
        message = f"SyntaxError: {exc.msg}"
    else:
        message = f"{type(exc).__name__}: {exc}"
    return message + (f" (program line {line})" if line else "")


def _on_alarm(signum, frame):
    raise ProgramTimeout


def run_trial(spec: TrialSpec) -> TrialRecord:
    """Runs one trial in this process; the program's time limit is enforced with a timer signal."""
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
        error = _execute(spec.program, tools.namespace(), spec.timeout, output := io.StringIO())
        backend.wait(1.0)  # let what was let go come to rest before judging
        results = [c.evaluate(backend.ground_truth).to_dict() for c in checks]
        return TrialRecord(
            task=spec.task,
            robot=spec.robot,
            trial=spec.trial,
            seed=spec.seed,
            ok=error is None,
            error=error,
            checks=results,
            sim_time_s=round(backend.time() - sim_start, 3),
            wall_time_s=round(time.perf_counter() - started, 3),
            output=output.getvalue()[:MAX_OUTPUT],
        )
    finally:
        if recorder is not None:
            recorder.close()
        backend.close()


def _execute(program: str, namespace: dict, timeout: float, output: io.StringIO) -> str | None:
    """Runs ``program`` in ``namespace``; returns ``None`` or the error that stopped it."""
    try:
        code = compile(program, PROGRAM_FILENAME, "exec")
    except SyntaxError as exc:
        return describe_exception(exc)
    namespace = dict(namespace)
    namespace["print"] = lambda *args, sep=" ", end="\n", **_: output.write(sep.join(map(str, args)) + end)
    previous = signal.signal(signal.SIGALRM, _on_alarm)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    try:
        exec(code, namespace)
        return None
    except ProgramTimeout:
        return f"TimeoutError: the program ran longer than its {timeout:g} s limit"
    except Exception as exc:
        return describe_exception(exc)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
