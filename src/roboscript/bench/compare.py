"""Benchmark runs side by side: one table per metric, a row per run (its policy, perception and robot), a column
per task; for the ablations (perception modes, with and without repair, LLMs, arms)."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

from roboscript.bench.metrics import METRICS
from roboscript.bench.results import LABELS
from roboscript.errors import InvalidArgumentError


def load_summary(run: Path) -> dict:
    """A run directory's ``summary.json``, with a clear error for anything else."""
    path = Path(run) / "summary.json"
    if not path.is_file():
        raise InvalidArgumentError(
            f"{run} is not a benchmark run directory (no summary.json); `roboscript bench` writes one"
        )
    return json.loads(path.read_text())


def run_label(summary: dict) -> str:
    run = summary["provenance"]
    perception = {"ground_truth": "gt"}.get(run.get("perception"), run.get("perception", "gt"))
    return f"`{run['policy']}`, {perception}, {run['robot']}"


def compare_runs(runs: Sequence[Path], metric: str = "all") -> str:
    """Markdown tables comparing ``runs``; tasks are those of the first run, in its order."""
    if not runs:
        raise InvalidArgumentError("give at least one run directory")
    summaries = [load_summary(r) for r in runs]
    tasks = list(summaries[0]["tasks"])
    metrics = METRICS if metric == "all" else (metric,)
    out = []
    for name in metrics:
        lines = [
            f"### {LABELS[name]}",
            "",
            "| Run | " + " | ".join(tasks) + " | Mean |",
            "|---|" + "---|" * (len(tasks) + 1),
        ]
        for summary in summaries:
            values = [summary["tasks"].get(t, {}).get(name) for t in tasks]
            cells = ["-" if v is None else f"{v:.2f}" for v in values]
            present = [v for v in values if v is not None]
            mean = f"{sum(present) / len(present):.2f}" if present else "-"
            trials = sum(summary["tasks"].get(t, {}).get("trials", 0) for t in tasks)
            lines.append(f"| {run_label(summary)} ({trials} trials) | " + " | ".join(cells) + f" | {mean} |")
        out.append("\n".join(lines))
    return "\n\n".join(out) + "\n"
