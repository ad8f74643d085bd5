"""``roboscript report``: runs side by side as markdown, CSV, PNG plots and one HTML page."""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from roboscript.bench.compare import compare_runs
from roboscript.bench.metrics import METRICS
from roboscript.report.page import write_page
from roboscript.report.runs import Run, find_runs

MAX_TASKS_PLOTTED = 40  # beyond this (a study's cells) tasks are drawn per object instead


@dataclass
class Report:
    runs: list[Run]
    markdown: str
    files: list[Path] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def _csv(runs: Sequence[Run]) -> str:
    out = io.StringIO()
    writer = csv.writer(out)
    writer.writerow(["run", "policy", "perception", "robot", "task", "trials", *METRICS])
    for run in runs:
        p = run.provenance
        for task, row in run.summary["tasks"].items():
            writer.writerow([run.path.name, p["policy"], p.get("perception", "gt"), p["robot"], task, row["trials"],
                             *(row[m] for m in METRICS)])  # fmt: skip
    return out.getvalue()


def _counts(run: Run, tasks: Sequence[str]) -> tuple[list[int], list[int]]:
    successes = [sum(r.success for r in run.records if r.task == t) for t in tasks]
    trials = [sum(1 for r in run.records if r.task == t) for t in tasks]
    return successes, trials


def _plots(runs: Sequence[Run], out: Path) -> list[Path]:
    from roboscript.bench.plots import grouped_bars

    plots = []
    tasks = list(dict.fromkeys(t for r in runs for t in r.tasks))
    if len(tasks) <= MAX_TASKS_PLOTTED:
        series = {run.label: _counts(run, tasks) for run in runs}
        title = "Whole-task success per task (95% Wilson intervals)"
        plots.append(grouped_bars(tasks, series, out / "success_by_task.png", title))
    if len(runs) > 1:
        totals = [_counts(run, tasks) for run in runs]
        series = {"all tasks": ([sum(s) for s, _ in totals], [sum(n) for _, n in totals])}
        title = "Whole-task success of each run over all its trials (95% Wilson intervals)"
        plots.append(grouped_bars([r.label for r in runs], series, out / "success_by_run.png", title))
    plots += _study_plots(runs, out)
    return plots


def _study_plots(runs: Sequence[Run], out: Path) -> list[Path]:
    """Per-object bars for runs whose tasks are a study's cells (``template.object.grasp``)."""
    from roboscript.objects import object_types
    from roboscript.study.cells import Cell
    from roboscript.study.run import object_plots
    from roboscript.study.tables import cell_results

    library = object_types()
    cells = []
    for run in runs:
        for task in run.tasks:
            try:
                cell = Cell.from_task_id(task)
            except ValueError:
                return []
            if cell.object not in library:
                return []
            cells.append(cell)
    results = cell_results([r for run in runs for r in run.records], list(dict.fromkeys(cells)))
    return object_plots("cells", results, out) if results else []


def write_report(paths: Sequence[str | Path], out: str | Path, metric: str = "all") -> Report:
    """Reads the runs at ``paths`` and writes ``report.md``, ``report.csv``, the plots and ``index.html`` into
    ``out``; plots are left out, with a note, where matplotlib is not installed."""
    runs = find_runs(paths)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    markdown = compare_runs([r.path for r in runs], metric)
    report = Report(runs, markdown)
    (out / "report.md").write_text(markdown)
    (out / "report.csv").write_text(_csv(runs))
    report.files += [out / "report.md", out / "report.csv"]
    plots: list[Path] = []
    try:
        plots = _plots(runs, out)
    except RuntimeError as exc:
        report.notes.append(f"no plots: {exc}")
    report.files += plots
    report.files.append(write_page(runs, plots, out / "index.html"))
    return report
