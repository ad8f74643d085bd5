"""A benchmark run's directory: per-trial records as JSON lines, provenance, and summary tables.

``results.jsonl`` gets one line per trial as soon as it ends, so an interrupted run loses nothing that finished
and resumes where it stopped. ``run.json`` holds the provenance (policy, programs' hashes, seeds, versions, git
commit); resuming with different programs or settings is refused rather than mixed. ``summary.md``, ``.csv`` and
``.json`` are rewritten after every trial.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import platform
import subprocess
import time
from collections import Counter
from collections.abc import Iterable
from dataclasses import replace
from importlib import metadata
from pathlib import Path
from typing import ClassVar

from roboscript.bench.metrics import METRICS, metrics
from roboscript.bench.trial import TrialRecord, TrialSpec
from roboscript.errors import InvalidArgumentError

LABELS = {
    "grammar_correctness": "Grammar correctness",
    "semantic_correctness": "Semantic correctness",
    "finished_steps_ratio": "Finished steps ratio",
    "whole_task_success": "Whole task success",
}


def program_hash(program: str) -> str:
    return hashlib.sha256(program.encode()).hexdigest()[:16]


def provenance(
    policy: str,
    robot: str,
    trials: int,
    seed: int,
    programs: dict[str, str],
    perception: str,
    repair_rounds: int = 0,
    suite: str = "paper",
    backend: str = "mujoco",
) -> dict:
    """Everything that decides a run's results, to be stored beside them (the backend where it is not MuJoCo)."""
    versions = {"python": platform.python_version()}
    for package in ("roboscript", "mujoco", "ompl", "mink", "numpy"):
        try:
            versions[package] = metadata.version(package)
        except metadata.PackageNotFoundError:
            versions[package] = "absent"
    return {
        "policy": policy,
        "suite": suite,
        "robot": robot,
        "trials": trials,
        "seed": seed,
        "perception": perception,
        "repair_rounds": repair_rounds,
        **({"backend": backend} if backend != "mujoco" else {}),
        "programs": {task: program_hash(p) for task, p in sorted(programs.items())},
        "versions": versions,
        "git_commit": _git_commit(),
        "host": platform.node(),
        "started": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
    }


def _git_commit() -> str | None:
    try:
        out = subprocess.run(
            ["git", "rev-parse", "HEAD"], capture_output=True, text=True, timeout=5, cwd=Path(__file__).parent
        )
        return out.stdout.strip() or None
    except (OSError, subprocess.SubprocessError):
        return None


class RunDirectory:
    """The files of one benchmark run; reopening it resumes the run."""

    # Settings that must match for a run to be resumed (a missing one counts as its default: runs from before it).
    # A run from before there were suites ran what is now the cluttered suite.
    FIXED: ClassVar[dict[str, object]] = {
        "policy": None,
        "suite": "cluttered",
        "robot": None,
        "seed": None,
        "perception": None,
        "repair_rounds": 0,
        "backend": "mujoco",
    }

    def __init__(self, path: str | Path, run: dict):
        self.path = Path(path)
        self.path.mkdir(parents=True, exist_ok=True)
        self.results = self.path / "results.jsonl"
        info = self.path / "run.json"
        if info.exists():
            previous = json.loads(info.read_text())
            if previous.get("perception") == "ground_truth":  # the name before there were perception modes
                previous["perception"] = "gt"
            for key, default in self.FIXED.items():
                if previous.get(key, default) != run.get(key, default):
                    raise InvalidArgumentError(
                        f"{self.path} holds a run with {key}={previous.get(key, default)!r}, not "
                        f"{run.get(key, default)!r}; "
                        "resume it with the same settings or choose another --out"
                    )
            for task, digest in run["programs"].items():
                old = previous.get("programs", {}).get(task)
                if old is not None and old != digest:
                    raise InvalidArgumentError(
                        f"{self.path} holds results of another program for {task} ({old}, now {digest}); "
                        "choose another --out"
                    )
            previous["programs"] = {**previous.get("programs", {}), **run["programs"]}
            previous["trials"] = max(previous.get("trials", 0), run["trials"])
            previous.setdefault("resumed", []).append(run["started"])
            # A run resumed from other code holds trials of each: every commit that wrote to it is kept.
            commits = previous.setdefault("git_commits", [previous.get("git_commit")])
            if run.get("git_commit") not in commits:
                commits.append(run.get("git_commit"))
            run = previous
        info.write_text(json.dumps(run, indent=2))
        self.run = run

    def records(self) -> list[TrialRecord]:
        """Records written so far; a line cut short by an interruption is ignored."""
        return read_records(self.results)

    def done(self) -> set[tuple[str, str, int]]:
        """The trials a resumed run does not run again: all recorded but those that never ran (their world or
        sandbox could not be set up there and then)."""
        return {(r.task, r.robot, r.trial) for r in self.records() if not r.never_ran}

    def append(self, record: TrialRecord) -> None:
        line = json.dumps(record.to_dict()) + "\n"
        with self.results.open("a+b") as f:  # appends go to the end wherever the file position is
            size = f.seek(0, 2)
            if size > 0:
                f.seek(size - 1)
                if f.read(1) != b"\n":  # a line cut short by a kill: ignored when read, so not glued onto
                    line = "\n" + line
            f.write(line.encode())
            f.flush()

    def write_summary(self, tasks: Iterable[str]) -> dict:
        records = self.records()
        summary = summarize(records, list(tasks), self.run)
        (self.path / "summary.json").write_text(json.dumps(summary, indent=2))
        (self.path / "summary.md").write_text(markdown_table(summary))
        (self.path / "summary.csv").write_text(csv_table(summary))
        return summary


def video_path(run_dir: Path, task: str, trial: int) -> Path:
    """Where a run keeps a trial's video when it keeps videos: ``<run>/videos/<task>_trial<i>.mp4``."""
    return run_dir / "videos" / f"{task}_trial{trial}.mp4"


VIDEO_CHOICES = ("none", "failed", "all")  # which trials of a run keep a video


def with_videos(specs: list[TrialSpec], run_dir: Path, videos: str) -> list[TrialSpec]:
    """The trials, each recording its video into the run (:func:`video_path`) unless ``videos`` is ``none``."""
    if videos not in VIDEO_CHOICES:
        raise InvalidArgumentError(f"unknown videos {videos!r}; choose one of: {', '.join(VIDEO_CHOICES)}")
    if videos == "none":
        return specs
    return [replace(s, video=str(video_path(run_dir, s.task, s.trial))) for s in specs]


def keep_video(spec: TrialSpec, record: TrialRecord, videos: str) -> None:
    """Deletes the video of a trial that succeeded where only failed trials keep theirs (``videos: failed``)."""
    if spec.video and videos == "failed" and record.success:
        Path(spec.video).unlink(missing_ok=True)


def read_records(results: Path) -> list[TrialRecord]:
    """The records of a ``results.jsonl``, the last of each trial (one that never ran is run again on resuming,
    and recorded again); a line cut short by an interruption is ignored."""
    if not results.exists():
        return []
    out: dict[tuple[str, str, int], TrialRecord] = {}
    for line in results.read_text().splitlines():
        try:
            record = TrialRecord(**json.loads(line))
        except (json.JSONDecodeError, TypeError):
            continue
        out[(record.task, record.robot, record.trial)] = record
    return list(out.values())


def summarize(records: list[TrialRecord], tasks: list[str], run: dict) -> dict:
    """Metrics per task; with repair also ``without_repair``: the same trials judged by their first attempt, which
    is what a run without repair would have done with the same programs."""
    by_task = {t: [r for r in records if r.task == t] for t in tasks}
    summary = {
        "provenance": run,
        "tasks": {t: {"trials": len(rs), **metrics(rs), "outcomes": _outcomes(rs)} for t, rs in by_task.items()},
    }
    if run.get("repair_rounds"):
        summary["without_repair"] = {}
        for t, rs in by_task.items():
            first = [r.first_attempt() for r in rs]
            summary["without_repair"][t] = {"trials": len(rs), **metrics(first), "outcomes": _outcomes(first)}
    return summary


def _outcomes(records: list[TrialRecord]) -> dict[str, int]:
    """How many trials ended in each outcome category, most frequent first."""
    return dict(Counter(r.outcome for r in records).most_common())


def _outcome_cell(outcomes: dict[str, int]) -> str:
    return ", ".join(f"{name} {count}" for name, count in outcomes.items()) or "-"


def markdown_table(summary: dict) -> str:
    """Metrics as rows and tasks as columns, as in the paper's table."""
    tasks = list(summary["tasks"])
    run = summary["provenance"]
    header = (
        f"Suite `{run.get('suite', 'cluttered')}`, policy `{run['policy']}`, robot `{run['robot']}`, "
        f"perception `{run['perception']}`\n\n"
    )
    lines = ["| Metric | " + " | ".join(tasks) + " |", "|---|" + "---|" * len(tasks)]
    rounds = run.get("repair_rounds")
    for metric in METRICS:
        if rounds:
            cells = [f"{summary['without_repair'][t][metric]:.2f}" for t in tasks]
            lines.append(f"| {LABELS[metric]}, no repair | " + " | ".join(cells) + " |")
        cells = [f"{summary['tasks'][t][metric]:.2f}" for t in tasks]
        label = f"{LABELS[metric]}, repair ≤{rounds}" if rounds else LABELS[metric]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    lines.append("| Trials | " + " | ".join(str(summary["tasks"][t]["trials"]) for t in tasks) + " |")
    if rounds:
        cells = [_outcome_cell(summary["without_repair"][t]["outcomes"]) for t in tasks]
        lines.append("| Outcomes, no repair | " + " | ".join(cells) + " |")
    label = f"Outcomes, repair ≤{rounds}" if rounds else "Outcomes"
    lines.append(f"| {label} | " + " | ".join(_outcome_cell(summary["tasks"][t]["outcomes"]) for t in tasks) + " |")
    note = ""
    if rounds:
        note = (
            "\n'no repair' judges the same trials by their first attempt: the program the LLM wrote first, run once.\n"
        )
    return header + "\n".join(lines) + "\n" + note


def csv_table(summary: dict) -> str:
    out = io.StringIO()
    writer = csv.writer(out)
    repaired = "without_repair" in summary
    writer.writerow(["task", "trials", *METRICS, *(f"{m}_no_repair" for m in METRICS if repaired)])
    for task, row in summary["tasks"].items():
        first = summary["without_repair"][task] if repaired else {}
        writer.writerow([task, row["trials"], *(row[m] for m in METRICS), *(first[m] for m in METRICS if repaired)])
    return out.getvalue()
