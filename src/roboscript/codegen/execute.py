"""A program run as every caller runs one (a benchmark trial, a run on a robot, its twin): the static checker
first, then, only where it finds nothing, the program in a confined process of its own, its tool calls answered
in this one."""

from __future__ import annotations

import time
from collections.abc import Callable

from roboscript.api import ToolAPI
from roboscript.codegen.checker import check_program
from roboscript.codegen.program_process import EXIT_GRACE, run_program
from roboscript.codegen.sandbox import MAX_ERROR, ExecutionResult, Limits, prepare, shortened


def check_and_execute(
    program: str,
    namespace: dict,
    limits: Limits,
    announce: Callable[[float | None], None] | None = None,
    stage: Callable[[str], None] | None = None,
) -> ExecutionResult:
    """Checks ``program`` and runs it against the tools of ``namespace`` within ``limits``. ``announce`` is told by
    when the run must be over, and ``None`` after it (a watchdog's); ``stage``, what is being done (for progress)."""
    stage = stage or _quiet
    if announce is not None:  # the checker's time is the program's too: the watchdog covers it
        announce(time.monotonic() + limits.timeout + EXIT_GRACE)
    stage("checking the program")
    refusal = checker_refusal(program)
    if refusal is not None:
        if announce is not None:
            announce(None)
        return refusal
    stage(f"running the program (time limit {limits.timeout:.0f} s)")
    return run_program(program, namespace, limits, forwarded=ToolAPI.TOOL_NAMES, announce=announce)


def checker_refusal(program: str) -> ExecutionResult | None:
    """What the static checker finds in ``program`` (syntax, unknown functions, bad arguments), as the result of a
    run that never started; None when it finds nothing."""
    findings = check_program(program)
    if not findings:
        return None
    error = "; ".join(f"{f.message} (program line {f.line})" for f in findings[:5])
    return ExecutionResult(findings[0].outcome, shortened(error, MAX_ERROR), "")


def static_refusal(program: str) -> ExecutionResult | None:
    """Why ``program`` would not run, found without running it: the checker's findings, then the guard's (what the
    sandbox refuses to run); None when both let it through. A command calls it once, before any trial."""
    refusal = checker_refusal(program)
    if refusal is not None:
        return refusal
    prepared = prepare(program)
    return prepared if isinstance(prepared, ExecutionResult) else None


def _quiet(what: str) -> None:
    pass
