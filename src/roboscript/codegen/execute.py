"""A program run as every caller runs one (a benchmark trial, a run on a robot, its twin): the static checker
first, then, only where it finds nothing, the program in a confined process of its own, its tool calls answered
in this one."""

from __future__ import annotations

import time
from collections.abc import Callable

from roboscript.api import ToolAPI
from roboscript.codegen.checker import check_program
from roboscript.codegen.program_process import EXIT_GRACE, run_program
from roboscript.codegen.sandbox import MAX_ERROR, ExecutionResult, Limits, shortened


def check_and_execute(
    program: str, namespace: dict, limits: Limits, announce: Callable[[float | None], None] | None = None
) -> ExecutionResult:
    """Checks ``program`` and runs it against the tools of ``namespace`` within ``limits``. ``announce`` is told by
    when the run must be over, and ``None`` after it (a watchdog's)."""
    if announce is not None:  # the checker's time is the program's too: the watchdog covers it
        announce(time.monotonic() + limits.timeout + EXIT_GRACE)
    findings = check_program(program)
    if findings:
        if announce is not None:
            announce(None)
        error = "; ".join(f"{f.message} (program line {f.line})" for f in findings[:5])
        return ExecutionResult(findings[0].outcome, shortened(error, MAX_ERROR), "")
    return run_program(program, namespace, limits, forwarded=ToolAPI.TOOL_NAMES, announce=announce)
