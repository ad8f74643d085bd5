"""What ``exec`` and ``run`` show of their trials: what each trial is doing while it runs, how it ended, what its
program printed and what the tools noticed for it, where its video and recording went; and the exit code the
trials give."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TextIO

from roboscript.codegen.outcomes import Outcome
from roboscript.notices import split_output

SUCCESS = 0  # every trial passed its task's checks (without a task: every program ran to its end)
TASK_FAILED = 1  # a trial did not: its program was refused, stopped on an error, or left the world short
USAGE = 2  # the command was given something it cannot use, or an optional part it needs is not installed
EXIT_STATUS_HELP = (
    "exit status: 0 when every trial passed its task's checks (without a task: when every program ran to its end); "
    "1 when a task failed (the program was refused, stopped on an error or left the world short of the checks); "
    "2 for a usage error, a missing optional part (the message says how to install it) or an LLM that could not be "
    "asked at all"
)


# How a trial's outcome reads in a trial's line (its name in JSON and results.jsonl is the key).
OUTCOME_WORDS = {
    Outcome.SYNTAX.value: "syntax error",
    Outcome.UNKNOWN_FUNCTION.value: "unknown function",
    Outcome.BAD_ARGUMENTS.value: "bad arguments",
    Outcome.FORBIDDEN_CONSTRUCT.value: "forbidden construct",
    Outcome.RUNTIME_ERROR.value: "stopped on an error",
    Outcome.PLANNING_FAILURE.value: "stopped: planning failed",
    Outcome.TIMEOUT.value: "stopped: out of time",
    Outcome.SANDBOX_VIOLATION.value: "stopped by the sandbox",
}


def llm_unreachable(records: Sequence) -> str | None:
    """The LLM's error where it could not be asked in any trial (so nothing ran), else None."""
    if records and all(r.outcome == Outcome.LLM_ERROR.value for r in records):
        return records[0].error
    return None


def throughput(trials: int, wall_s: float, jobs: int | None = None) -> str:
    """``80 trials in 195 s: 1,477 trials an hour with 2 jobs``: how fast a run went, as runs are compared."""
    at_once = f" with {jobs} job{'s' if jobs != 1 else ''}" if jobs else ""
    if trials == 0 or wall_s <= 0:
        return f"{trials} trials in {wall_s:.0f} s"
    counted = f"{trials} trial{'s' if trials != 1 else ''}"
    return f"{counted} in {wall_s:.0f} s: {trials / wall_s * 3600:,.0f} trials an hour{at_once}"


def exit_code(records: Sequence, checked: bool = True) -> int:
    """:data:`SUCCESS` when every trial passed (``checked``: its checks; else: its program ran to its end)."""
    passed = all(r.success for r in records) if checked else all(r.ok for r in records)
    return SUCCESS if records and passed else TASK_FAILED


def stage_printer(stream: TextIO | None = None, clock=time.monotonic) -> Callable[[object, str], None]:
    """Shows what a trial is doing as it reports it: ``[  4.1 s] trial 0: running the program (time limit 300 s)``."""
    started = clock()

    def show(spec, text: str) -> None:
        print(f"[{clock() - started:6.1f} s] trial {spec.trial}: {text}", file=stream or sys.stderr, flush=True)

    return show


def output_lines(output: str, indent: str = "    ") -> list[str]:
    """A program's output, labelled: what it printed, then what the tools noticed on its behalf."""
    printed, notices = split_output(output)
    lines = []
    if printed:
        lines += [f"{indent}printed:"] + [f"{indent}  {text}" for text in printed]
    if notices:
        lines += [f"{indent}notices:"] + [f"{indent}  {text}" for text in notices]
    return lines


def files_written(specs: Sequence) -> dict[int, list[str]]:
    """Each trial's video and recording, where the trial wrote them: ``{trial: ["video: PATH", ...]}``."""
    written: dict[int, list[str]] = {}
    for spec in specs:
        for what, path in (("video", spec.video), ("recording", spec.record)):
            if path and Path(path).is_file():
                written.setdefault(spec.trial, []).append(f"{what}: {path}")
    return written


def print_result(
    result: dict, checked: bool = True, written: dict[int, list[str]] | None = None, stream: TextIO | None = None
) -> None:
    """A task's result as ``exec`` and ``run`` print it: the metrics (or, without a task, that nothing was checked),
    then each trial's end, output, error, failed checks and files."""
    stream = stream or sys.stdout
    trials = f"{result['trials']} trial{'s' if result['trials'] != 1 else ''}"
    if checked:
        print(
            f"{result['task']} ({result['robot']}, {trials}): grammar {result['grammar_correctness']:.2f}, "
            f"semantic {result['semantic_correctness']:.2f}, finished steps {result['finished_steps_ratio']:.2f}, "
            f"whole task {result['whole_task_success']:.2f}",
            file=stream,
        )
    else:
        print(f"{result['task']} ({result['robot']}, {trials}): the world has no task, so nothing was checked",
              file=stream)  # fmt: skip
    for trial in result["per_trial"]:
        print("\n".join(_trial_lines(trial, checked, (written or {}).get(trial["trial"], []))), file=stream)


def _trial_lines(trial: dict, checked: bool, files: list[str]) -> list[str]:
    passed = sum(c["passed"] for c in trial["checks"])
    written = trial["outcome"] != Outcome.LLM_ERROR.value
    if not written:
        status, checked = "no program: the LLM could not be asked", False  # nothing ran, so there is nothing to judge
    elif not trial["ok"]:
        status = OUTCOME_WORDS.get(trial["outcome"], trial["outcome"].replace("_", " "))
    elif not checked:
        status = "ran to its end"
    else:
        status = "passed" if trial["checks"] and passed == len(trial["checks"]) else "checks failed"
    head = f"  trial {trial['trial']} (seed {trial['seed']}): {status}"
    if checked:
        head += f", {passed}/{len(trial['checks'])} checks"
    lines = [head + f", sim {trial['sim_time_s']:.1f} s, wall {trial['wall_time_s']:.1f} s"]
    lines += output_lines(trial.get("output", ""))
    if trial["error"]:
        lines.append(f"    error: {trial['error']}")
    if checked:
        lines += [f"    failed: {c['check']}: {c['detail']}" for c in trial["checks"] if not c["passed"]]
    lines += [f"    {line}" for line in files]
    return lines


def print_refusal(program: str, refusal, stream: TextIO | None = None) -> None:
    """A program the checks refused before any trial: said once, with every finding."""
    what = refusal.outcome.value.replace("_", " ")
    print(
        f"{program}: not run: refused before any trial ({what})\n  {refusal.error}",
        file=stream or sys.stdout,
    )
