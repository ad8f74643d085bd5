"""Running a study: its cells as a sweep (:mod:`roboscript.study.sweep`), then its tables and per-object plots."""

from __future__ import annotations

import json
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from roboscript.errors import InvalidArgumentError
from roboscript.study.cells import Cell
from roboscript.study.study_file import load_study
from roboscript.study.sweep import Executor, run_sweep
from roboscript.study.sweep_file import StudySelection, Sweep
from roboscript.study.tables import CellResult, cell_results, study_csv, study_markdown


@dataclass
class StudyOutcome:
    results: list[CellResult]
    files: list[Path]
    wall_time_s: float


def study_sweep(
    name: str,
    robots: Sequence[str],
    trials: int,
    seed: int = 0,
    templates: Sequence[str] | None = None,
    objects: Sequence[str] | None = None,
    grasps: Sequence[str] | None = None,
    timeout: float = 300.0,
    videos: str = "none",
) -> Sweep:
    """The sweep that runs a study's chosen cells with the reference programs on ``robots``."""
    selection = StudySelection(
        name,
        None if templates is None else tuple(templates),
        None if objects is None else tuple(objects),
        None if grasps is None else tuple(grasps),
    )
    return Sweep(
        name=f"study_{name}",
        study=selection,
        robots=tuple(robots),
        trials=trials,
        seed=seed,
        timeout=timeout,
        videos=videos,
    )


def run_study(sweep: Sweep, out: str | Path, executor: Executor, progress: bool = True) -> StudyOutcome:
    """Runs (or resumes) the study's sweep into ``out`` and writes ``study.md``, ``study.csv``, ``study.json`` and
    a bar chart per robot and grasp tool (``objects_<robot>_<grasp>.png``) beside the run directories."""
    if sweep.study is None:
        raise InvalidArgumentError("run_study needs a study's sweep (see study_sweep)")
    out = Path(out)
    started = time.perf_counter()
    runs = run_sweep(sweep, out, executor, progress)
    wall = time.perf_counter() - started
    cells = [Cell.from_task_id(task) for task in runs[0].tasks]  # the sweep's tasks are the chosen cells
    records = [r for run in runs for r in run.directory.records() if r.trial < sweep.trials]
    results = cell_results(records, cells)
    files = write_study_report(load_study(sweep.study.name).name, results, out, wall)
    return StudyOutcome(results, files, wall)


def write_study_report(name: str, results: list[CellResult], out: Path, wall_time_s: float | None) -> list[Path]:
    """The study's tables and plots in ``out``; the plots are skipped, with a note, where matplotlib is absent."""
    files = [out / "study.md", out / "study.csv", out / "study.json"]
    files[0].write_text(study_markdown(name, results, wall_time_s))
    files[1].write_text(study_csv(results))
    files[2].write_text(json.dumps({"study": name, "cells": [r.to_dict() for r in results]}, indent=1))
    try:
        files += object_plots(name, results, out)
    except RuntimeError as exc:  # no matplotlib: the tables stand on their own
        print(f"study: no plots: {exc}")
    return files


def object_plots(name: str, results: list[CellResult], out: Path) -> list[Path]:
    """Per robot and grasp tool, the success of every object (grouped by shape) with a bar per template."""
    from roboscript.bench.plots import grouped_bars

    paths = []
    for robot in sorted({r.robot for r in results}):
        for grasp in dict.fromkeys(r.grasp for r in results if r.robot == robot):
            mine = sorted((r for r in results if r.robot == robot and r.grasp == grasp), key=lambda r: r.shape)
            objects = list(dict.fromkeys(r.object for r in mine))
            series = {}
            for template in dict.fromkeys(r.template for r in mine):
                by_object = {r.object: r for r in mine if r.template == template}
                series[template] = (
                    [by_object[o].successes if o in by_object else 0 for o in objects],
                    [by_object[o].trials if o in by_object else 0 for o in objects],
                )
            labels = [f"{o} ({next(r.shape for r in mine if r.object == o)})" for o in objects]
            title = f"Study {name}: success per object, {robot}, {grasp} grasp (95% Wilson intervals)"
            paths.append(grouped_bars(labels, series, out / f"objects_{robot}_{grasp}.png", title))
    return paths
