"""The demo: one benchmark task end to end, with a video and a report a person can read.

The program comes from the LLM the environment configures (``ROBOSCRIPT_LLM``, or ``ROBOSCRIPT_LLM_MODEL`` with
``ROBOSCRIPT_LLM_BASE_URL``); where none is configured, from the task's reference program, and the report says so.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

from roboscript.bench.runner import run_isolated
from roboscript.bench.tasks import DEFAULT_SUITE, get_task
from roboscript.bench.trial import LLMAuthor, TrialRecord, TrialSpec
from roboscript.llm.openai_compatible import MODEL_ENV
from roboscript.notices import split_output
from roboscript.perception.modes import GROUND_TRUTH, PerceptionMode

DEMO_TASK = "simple_0"


@dataclass(frozen=True)
class DemoPlan:
    """What the demo will run: ``llm`` is None when the reference program runs."""

    task: str
    robot: str
    llm: str | None
    out: Path
    suite: str = DEFAULT_SUITE

    @property
    def source(self) -> str:
        if self.llm is not None:
            return f"written by the LLM {self.llm}"
        return (
            f"the reference program of {self.task}: no LLM is configured "
            f"(set ROBOSCRIPT_LLM, e.g. openai:MODEL@URL or llama:PATH.gguf, or {MODEL_ENV})"
        )


def run_demo(
    plan: DemoPlan,
    seed: int = 0,
    timeout: float = 300.0,
    repair_rounds: int = 0,
    perception: PerceptionMode | str = GROUND_TRUTH,
    backend: str = "mujoco",
) -> TrialRecord:
    """Runs the task once in a child process; writes ``<task>.mp4``, ``report.md`` and ``report.json`` in
    ``plan.out``."""
    task = get_task(plan.task, plan.suite)
    plan.out.mkdir(parents=True, exist_ok=True)
    video = plan.out / f"{plan.task}.mp4"
    video.unlink(missing_ok=True)  # a video from an earlier demo must not pass for this one's
    program = "" if plan.llm is not None else task.reference_program()
    spec = TrialSpec(
        plan.task,
        plan.robot,
        0,
        seed,
        LLMAuthor(plan.llm, repair_rounds) if plan.llm is not None else program,
        timeout,
        None if backend == "ros" else str(video),  # through ROS no video is recorded yet
        perception=perception,
        suite=plan.suite,
        backend=backend,
    )
    (record,) = run_isolated([spec])
    if plan.llm is None:
        record.program = program
    report = {
        "task": plan.task,
        "suite": plan.suite,
        "instruction": task.instruction,
        "query": task.query,
        "robot": plan.robot,
        "seed": seed,
        "perception": str(perception),
        "program_source": plan.source,
        "video": str(video) if video.is_file() else None,
        "record": record.to_dict(),
    }
    (plan.out / "report.json").write_text(json.dumps(report, indent=2))
    (plan.out / "report.md").write_text(report_markdown(report, record))
    return record


def report_markdown(report: dict, record: TrialRecord) -> str:
    """The demo's report: the instruction, where the program came from, what happened, and the program."""
    lines = [
        f"# RoboScript demo: {report['task']} on the {report['robot']}",
        "",
        f'Instruction: "{report["instruction"]}"',
        "",
        f"Program: {report['program_source']}.",
        "",
        f"Outcome: **{record.outcome}**, {record.passed}/{len(record.checks)} checks passed"
        f" ({'task done' if record.success else 'task not done'}).",
    ]
    if record.error:
        lines += ["", f"Error: `{record.error}`"]
    lines += [
        "",
        f"The robot's motion took {record.sim_time_s:.1f} s of simulated time; the whole run {record.wall_time_s:.1f} s"
        " of wall time (building the world, rendering the video and any LLM calls included).",
        "",
        "| Check | Passed | Detail |",
        "|---|---|---|",
    ]
    for check in record.checks:
        lines.append(f"| {check['check']} | {'yes' if check['passed'] else 'no'} | {check.get('detail', '')} |")
    if report["video"]:
        lines += ["", f"Video: `{report['video']}`"]
    if record.program:
        lines += ["", "## Program", "", "```python", record.program.rstrip(), "```"]
    printed, notices = split_output(record.output)
    for title, text in (("Printed by the program", printed), ("Notices from the tools", notices)):
        if text:
            lines += ["", f"## {title}", "", "```", *text, "```"]
    return "\n".join(lines) + "\n"
