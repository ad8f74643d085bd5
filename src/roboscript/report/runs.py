"""The runs a report is about: run directories given directly, or found one level inside the folders given (a
sweep's or a study's output), each with its summary and trial records."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from roboscript.bench.results import read_records, video_path
from roboscript.bench.trial import TrialRecord


@dataclass
class Run:
    """One run directory: its summary (``summary.json``), its records and the label it goes by in a report."""

    path: Path
    summary: dict
    records: list[TrialRecord]
    label: str = ""

    def __post_init__(self) -> None:
        if not self.label:
            p = self.provenance
            self.label = f"{p['policy']} · {p.get('perception', 'gt')} · {p['robot']}"

    @property
    def provenance(self) -> dict:
        return self.summary["provenance"]

    @property
    def tasks(self) -> list[str]:
        return list(self.summary["tasks"])

    def failed(self) -> list[TrialRecord]:
        """The trials that did not succeed, in the order of the run's tasks, then by trial."""
        order = {task: i for i, task in enumerate(self.tasks)}
        failed = (r for r in self.records if not r.success)
        return sorted(failed, key=lambda r: (order.get(r.task, len(order)), r.trial))

    def video(self, record: TrialRecord) -> Path | None:
        """The trial's video where a sweep kept one."""
        path = video_path(self.path, record.task, record.trial)
        return path if path.is_file() else None


def find_runs(paths: Sequence[str | Path]) -> list[Run]:
    """The run directories among ``paths`` and one level inside them, in the order given (then by name)."""
    found: list[Path] = []
    for given in map(Path, paths):
        if (given / "summary.json").is_file():
            found.append(given)
        elif given.is_dir():
            inner = sorted(p for p in given.iterdir() if (p / "summary.json").is_file())
            if not inner:
                raise ValueError(f"{given} holds no benchmark run (no summary.json in it or its folders)")
            found += inner
        else:
            raise ValueError(f"{given} is not a folder; give run directories or the folders of sweeps and studies")
    runs = []
    for path in dict.fromkeys(found):
        summary = json.loads((path / "summary.json").read_text())
        runs.append(Run(path, summary, read_records(path / "results.jsonl")))
    labels = [r.label for r in runs]
    for run in runs:  # runs of the same settings (two suites, two sweeps) are told apart by their folders
        if labels.count(run.label) > 1:
            run.label = f"{run.label} ({run.path.parent.name}/{run.path.name})"
    return runs
