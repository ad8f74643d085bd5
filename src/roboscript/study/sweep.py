"""Sweeps: every combination of policy, robot and perception mode over a suite's tasks (or a study's cells) and
trials, as independent jobs on a local process pool or a Ray cluster.

Each combination is a run directory of its own (:class:`~roboscript.bench.results.RunDirectory`), the same as
``roboscript bench`` writes, so ``roboscript report`` reads it and an interrupted sweep resumes where it stopped:
trials already in a run's ``results.jsonl`` are not run again, and each trial's record is appended the moment it
ends, by this process only (jobs on other machines send their records back).
"""

from __future__ import annotations

import re
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from roboscript.bench.benchmark import folder_label, open_run, policy_programs
from roboscript.bench.progress import ProgressBar
from roboscript.bench.results import RunDirectory, keep_video, with_videos
from roboscript.bench.trial import TrialRecord, TrialSpec
from roboscript.perception.modes import parse_mode
from roboscript.study.sweep_file import Sweep

SUMMARY_INTERVAL = 10.0  # seconds between rewrites of a run's summary while trials end (and once at the end)


@dataclass
class PlannedRun:
    """One combination of a sweep: its run directory, its tasks, and the trials it still needs."""

    name: str
    policy: str
    robot: str
    perception: str
    directory: RunDirectory
    tasks: list[str]
    pending: list[TrialSpec] = field(default_factory=list)


def run_name(policy: str, robot: str, perception: str, repair_rounds: int = 0) -> str:
    """``<policy>_<robot>_<perception>``, safe for a folder name (``llm-gpt-4o+repair1_panda_gt``; the policy as
    :func:`~roboscript.bench.benchmark.folder_label` names it)."""
    return re.sub(r"[^A-Za-z0-9._+-]+", "_", f"{folder_label(policy, repair_rounds)}_{robot}_{perception}")


def sweep_suite(sweep: Sweep, out: Path) -> tuple[str, list[str]]:
    """The suite the sweep's trials name and its task ids: a study's cells are written out as a suite in
    ``out/suite`` first (:mod:`roboscript.study.cells`)."""
    if sweep.study is not None:
        from roboscript.study.cells import select_cells, write_suite
        from roboscript.study.study_file import load_study

        study = load_study(sweep.study.name)
        cells = select_cells(study, sweep.study.templates, sweep.study.objects, sweep.study.grasps)
        path = write_suite(study, cells, out / "suite")
        return str(path.resolve()), [c.task_id for c in cells]
    from roboscript.bench.tasks import load_suite

    return sweep.suite, list(sweep.tasks or load_suite(sweep.suite))


def plan_sweep(sweep: Sweep, out: str | Path) -> list[PlannedRun]:
    """Opens (or reopens) the run directory of every combination under ``out`` and lists the trials each still
    needs; a run directory holding results of other settings or programs is refused, as ``bench`` refuses it."""
    out = Path(out)
    suite, tasks = sweep_suite(sweep, out)
    runs = []
    for policy in sweep.policies:
        programs = policy_programs(policy, tasks, suite)
        for robot in sweep.robots:
            for perception in sweep.perception:
                name = run_name(policy, robot, perception, sweep.repair_rounds)
                directory, pending = open_run(
                    out / name,
                    policy,
                    tasks,
                    robot,
                    sweep.trials,
                    sweep.seed,
                    sweep.timeout,
                    sweep.repair_rounds,
                    parse_mode(perception),
                    suite,
                    programs=programs,
                )
                pending = with_videos(pending, directory.path, sweep.videos)
                runs.append(PlannedRun(name, policy, robot, perception, directory, tasks, pending))
    return runs


class Executor:
    """Runs trial specs and hands each back with its record as it ends (``on_result(spec, record)``)."""

    def run(self, specs: list[TrialSpec], on_result: Callable[[TrialSpec, TrialRecord], None]) -> None:
        raise NotImplementedError


class LocalExecutor(Executor):
    """A process pool on this machine (:class:`roboscript.bench.runner.TrialPool`)."""

    def __init__(self, jobs: int):
        self.jobs = jobs

    def run(self, specs: list[TrialSpec], on_result: Callable[[TrialSpec, TrialRecord], None]) -> None:
        from roboscript.bench.runner import TrialPool

        with TrialPool(self.jobs) as pool:
            pool.run(specs, on_result=on_result)


def run_sweep(sweep: Sweep, out: str | Path, executor: Executor, progress: bool = True) -> list[PlannedRun]:
    """Runs (or resumes) ``sweep`` into ``out``: every pending trial of every run, interleaved (run by run, task
    by task, trial by trial), each record appended to its run as it ends; returns the runs."""
    runs = plan_sweep(sweep, out)
    owner: dict[int, PlannedRun] = {}
    specs: list[TrialSpec] = []
    for run in runs:
        for spec in run.pending:
            owner[id(spec)] = run
            specs.append(spec)
    total = sum(len(r.tasks) for r in runs) * sweep.trials
    bar = ProgressBar(total, total - len(specs)) if progress else None
    last_summary = [time.monotonic()]

    def on_result(spec: TrialSpec, record: TrialRecord) -> None:
        run = owner[id(spec)]
        run.directory.append(record)
        keep_video(spec, record, sweep.videos)
        if bar is not None:
            bar.update(record, f"{run.name} {record.task}")
        if time.monotonic() - last_summary[0] > SUMMARY_INTERVAL:
            for r in runs:
                r.directory.write_summary(r.tasks)
            last_summary[0] = time.monotonic()

    try:
        if specs:
            executor.run(specs, on_result)
    finally:
        for run in runs:
            run.directory.write_summary(run.tasks)
    return runs
