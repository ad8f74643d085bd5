"""The runs a report is about: run directories given directly, or found one level inside the folders given (a
sweep's or a study's output), each with its summary and trial records."""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

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
        return sorted((r for r in self.records if not r.success), key=lambda r: (self.tasks.index(r.task)
                      if r.task in self.tasks else len(self.tasks), r.trial))  # fmt: skip

    def video(self, record: TrialRecord) -> Path | None:
        """The trial's video where one was kept (a sweep's ``videos/<task>_trial<i>.mp4``)."""
        path = self.path / "videos" / f"{record.task}_trial{record.trial}.mp4"
        return path if path.is_file() else None


def _records(path: Path) -> list[TrialRecord]:
    out = []
    results = path / "results.jsonl"
    if results.is_file():
        for line in results.read_text().splitlines():
            try:
                out.append(TrialRecord(**json.loads(line)))
            except (json.JSONDecodeError, TypeError):  # a line cut short by a kill
                continue
    return out


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
        runs.append(Run(path, summary, _records(path)))
    labels = [r.label for r in runs]
    for run in runs:  # runs of the same settings (two suites, two sweeps) are told apart by their folders
        if labels.count(run.label) > 1:
            run.label = f"{run.label} ({run.path.parent.name}/{run.path.name})"
    return runs
