"""One HTML page of a report: each run's provenance, the metric tables, the plots and every failed trial with its
error and, where one was kept, its video. Self-contained apart from the plots and videos it links beside it."""

from __future__ import annotations

import html
import os
from collections.abc import Sequence
from pathlib import Path

from roboscript import extras
from roboscript.bench.metrics import METRICS
from roboscript.bench.results import LABELS
from roboscript.notices import split_output
from roboscript.report.runs import Run

STYLE = """
body { font-family: system-ui, sans-serif; margin: 2em auto; max-width: 1200px; color: #222; }
h1 { font-size: 1.6em; } h2 { margin-top: 1.6em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; } th { background: #f3f3f3; }
td.name, th.name { text-align: left; } td.fail { background: #fbe3e3; } td.pass { background: #e3f5e3; }
img { max-width: 100%; border: 1px solid #eee; margin: 0.5em 0; }
.trial { border: 1px solid #ddd; border-radius: 4px; padding: 0.5em 1em; margin: 0.8em 0; }
.trial pre { white-space: pre-wrap; background: #f8f8f8; padding: 0.5em; font-size: 0.85em; }
video { max-width: 480px; display: block; } .muted { color: #777; } .wide { overflow-x: auto; }
"""


def _e(text: object) -> str:
    return html.escape(str(text))


def _metric_table(runs: Sequence[Run], metric: str) -> str:
    """A row per task (a study has hundreds), a column per run."""
    tasks = list(dict.fromkeys(t for r in runs for t in r.tasks))
    head = "".join(f"<th>{_e(r.label)}</th>" for r in runs)
    rows = []
    for t in tasks:
        cells = []
        for run in runs:
            row = run.summary["tasks"].get(t)
            if row is None:
                cells.append("<td>-</td>")
                continue
            value = row[metric]
            css = "pass" if value >= 0.999 else ("fail" if value <= 0.001 else "")
            cells.append(f'<td class="{css}">{value:.2f}</td>')
        rows.append(f'<tr><td class="name">{_e(t)}</td>{"".join(cells)}</tr>')
    return f'<div class="wide"><table><tr><th class="name">Task</th>{head}</tr>{"".join(rows)}</table></div>'


def _provenance(runs: Sequence[Run]) -> str:
    keys = ("policy", "suite", "robot", "perception", "trials", "seed", "repair_rounds", "git_commit", "started")
    head = "".join(f"<th>{k}</th>" for k in keys)
    rows = []
    for run in runs:
        p = run.provenance
        shown = {**p, "suite": Path(str(p.get("suite", "-"))).name, "git_commit": str(p.get("git_commit"))[:10]}
        cells = "".join(f'<td class="name">{_e(shown.get(k, "-"))}</td>' for k in keys)
        trials = len(run.records)
        rows.append(f'<tr><td class="name">{_e(run.path.name)}</td>{cells}<td>{trials}</td></tr>')
    return f'<table><tr><th class="name">Run directory</th>{head}<th>records</th></tr>{"".join(rows)}</table>'


FOLD_FROM = 20  # failed trials in a run from which each task's failures start folded


def _trial(run: Run, record, page_dir: Path) -> str:
    checks = ", ".join(f"{c['check']}: {'passed' if c['passed'] else 'failed'} ({c['detail']})"
                       for c in record.checks) or "none evaluated"  # fmt: skip
    video = run.video(record)
    media = (
        f'<video controls preload="metadata" src="{_e(os.path.relpath(video, page_dir))}"></video>'
        if video
        else '<p class="muted">no video kept (bench --videos failed, or videos: failed in a sweep, keeps them)</p>'
    )
    error = f"<pre>{_e(record.error)}</pre>" if record.error else ""
    return (
        f'<div class="trial"><b>{_e(record.task)}</b>, trial {record.trial} (seed {record.seed}): '
        f"<b>{_e(record.outcome)}</b>; checks: {_e(checks)}; simulated {record.sim_time_s:.1f} s"
        f"{error}{_output(record.output)}{media}</div>"
    )


def _output(output: str) -> str:
    """What the program printed and what the tools noticed for it, each under its label."""
    printed, notices = split_output(output)
    parts = [
        f'<p class="muted">{label}</p><pre>{_e(chr(10).join(lines))}</pre>'
        for label, lines in (("printed by the program", printed), ("notices from the tools", notices))
        if lines
    ]
    return "".join(parts)


def _failed_trials(runs: Sequence[Run], page_dir: Path) -> str:
    """Every failed trial, grouped by task; a run with many failures (a study's) shows each task folded."""
    parts = []
    for run in runs:
        failed = run.failed()
        if not failed:
            continue
        parts.append(f"<h3>{_e(run.label)}: {len(failed)} of {len(run.records)} trials failed</h3>")
        by_task: dict[str, list] = {}
        for record in failed:
            by_task.setdefault(record.task, []).append(record)
        opened = " open" if len(failed) < FOLD_FROM else ""
        for task, records in by_task.items():
            trials = "".join(_trial(run, r, page_dir) for r in records)
            parts.append(
                f"<details{opened}><summary><b>{_e(task)}</b>: {len(records)} failed</summary>{trials}</details>"
            )
    return "\n".join(parts) or "<p>No trial failed.</p>"


def write_page(runs: Sequence[Run], plots: Sequence[Path], path: Path, title: str = "RoboScript report") -> Path:
    """Writes the report's page to ``path``; plots and videos are linked relative to it."""
    page_dir = path.parent
    figures = "\n".join(f'<img src="{_e(os.path.relpath(p, page_dir))}" alt="{_e(p.stem)}">' for p in plots)
    tasks = {t for r in runs for t in r.tasks}
    opened = " open" if len(tasks) <= FOLD_FROM else ""  # a study's hundreds of cells: folded
    counted = f"{len(tasks)} task{'s' if len(tasks) != 1 else ''}"
    tables = "\n".join(
        f"<details{opened}><summary><b>{LABELS[m]}</b> ({counted})</summary>{_metric_table(runs, m)}</details>"
        for m in METRICS
    )
    body = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{_e(title)}</title><style>{STYLE}</style></head>
<body>
<h1>{_e(title)}</h1>
<h2>Runs</h2>
<div class="wide">{_provenance(runs)}</div>
<h2>Plots</h2>
{figures or f'<p class="muted">no plots ({_e(extras.missing_text("report", "plots"))})</p>'}
<h2>Metrics</h2>
{tables}
<h2>Failed trials</h2>
{_failed_trials(runs, page_dir)}
</body></html>
"""
    path.write_text(body)
    return path
