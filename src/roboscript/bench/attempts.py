"""One attempt at a trial as its record keeps it, whichever way its world was run (simulated, through ROS, through
libfranka): the program's outcome with the task's checks, and who judged it."""

from __future__ import annotations

import os

from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import ExecutionResult

MAX_OUTPUT = 4000  # characters of a program's printed output kept in its record


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
