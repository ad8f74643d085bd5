"""One attempt's world, whichever way it is run (simulated here, served through ROS, driven through libfranka):
built before the program runs, judged after, closed; and the attempt as the trial's record keeps it (the
program's outcome with the task's checks, and who judged it)."""

from __future__ import annotations

import os
from abc import ABC, abstractmethod

from roboscript.backends.base import Backend
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult
from roboscript.phases import phase

MAX_OUTPUT = 4000  # characters of a program's printed output kept in its record


class TrialWorld(ABC):
    """A task's world for one attempt of ``spec`` (a :class:`~roboscript.bench.trial.TrialSpec`) at ``task``: a
    context that builds it (:meth:`build`: its ``backend`` and the tools' ``namespace``), in which the program
    runs and is judged (:meth:`judge`), and which closes what it made, whether or not the building finished."""

    backend: Backend | None = None
    namespace: dict

    def __init__(self, spec, task):
        self.spec, self.task = spec, task

    def __enter__(self) -> TrialWorld:
        with phase("build"):
            try:
                self.build()
            except BaseException:
                self.close(built=False)
                raise
        self.sim_start = self.backend.time()
        return self

    def __exit__(self, *exc) -> None:
        self.close(built=True)

    @abstractmethod
    def build(self) -> None:
        """Makes the world: sets :attr:`backend` and :attr:`namespace`."""

    @abstractmethod
    def judge(self, result: ExecutionResult) -> dict:
        """The attempt's record (:func:`attempt_record`) once what was let go has come to rest."""

    @abstractmethod
    def close(self, built: bool) -> None:
        """Closes what :meth:`build` made (all of it, or as far as it got where ``built`` is false)."""


def attempt_record(result: ExecutionResult, checks: list[dict], sim_time: float) -> dict:
    """An attempt as the trial record keeps it: a program that ran to its end fails if a check did not pass."""
    outcome = result.outcome
    if outcome is Outcome.OK and not all(c["passed"] for c in checks):
        outcome = Outcome.CHECKS_FAILED
    return {
        "outcome": outcome.value,
        "ok": result.error is None,
        "error": result.error,
        "checks": checks,
        "sim_time_s": round(sim_time, 3),
        "output": result.output[:MAX_OUTPUT],
        "judged_by": judged_by(result),
    }


def judged_by(result: ExecutionResult) -> str:
    """Who judged an attempt: this process, from the world's state, after the program's process ended."""
    where = f"; the program ran in {result.ran_in}" if result.ran_in else "; no program ran"
    return f"the trial's process {os.getpid()}, from the world's state{where}"
