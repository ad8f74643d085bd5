"""The program corpus as a benchmark: every style of ``tests/data/program_corpus`` and the reference programs, on one
arm, with a table of whole-task success per program and the median wall time of a trial.

Run: python benchmarks/corpus.py [--robot panda] [--trials 10] [--jobs 2] [--styles gpt_style,...,reference]
                                 [--out out/corpus]

Each style runs as ``roboscript bench --policy programs:<style folder>`` (the reference as ``--policy reference``)
into ``<out>/<style>_<robot>``, a run directory: an interrupted run resumes where it stopped, and a finished one is
only read. Progress is the benchmark's own, printed as each trial ends. Run two at once (one per arm) to measure
under load: no figure here is a timing assertion, and wall times depend on what else the machine does.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "data" / "program_corpus"
TASKS = ("simple_0", "simple_1", "moderate_0", "moderate_1", "moderate_2", "hard_0", "hard_1", "hard_2")


def styles_available() -> list[str]:
    return [*sorted(p.name for p in CORPUS.iterdir() if p.is_dir()), "reference"]


def run_style(style: str, robot: str, trials: int, jobs: int, out: Path) -> Path:
    """Runs (or resumes) one style's benchmark; returns its run directory."""
    policy = "reference" if style == "reference" else f"programs:{CORPUS / style}"
    directory = out / f"{style}_{robot}"
    command = [sys.executable, "-m", "roboscript.cli", "bench", "--policy", policy, "--robot", robot]
    command += ["--trials", str(trials), "--jobs", str(jobs), "--out", str(directory)]
    subprocess.run(command, check=False)
    return directory


def row(directory: Path) -> tuple[list[str], int, int]:
    """Per task 'success (median wall s)', and the successes and trials over all tasks."""
    results = directory / "results.jsonl"
    lines = results.read_text().splitlines() if results.exists() else []
    records = [json.loads(line) for line in lines if line.strip()]
    cells, passed = [], 0
    for task in TASKS:
        mine = [r for r in records if r["task"] == task]
        ok = sum(1 for r in mine if r["checks"] and all(c["passed"] for c in r["checks"]))
        passed += ok
        wall = statistics.median(r["wall_time_s"] for r in mine) if mine else 0.0
        cells.append(f"{ok / len(mine):.1f} ({wall:.0f})" if mine else "-")
    return cells, passed, len(records)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", default="panda", choices=("panda", "ur5e"))
    parser.add_argument("--trials", type=int, default=10)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--styles", default=",".join(styles_available()))
    parser.add_argument("--out", default="out/corpus")
    args = parser.parse_args()
    styles = [s.strip() for s in args.styles.split(",") if s.strip()]
    unknown = sorted(set(styles) - set(styles_available()))
    if unknown:
        parser.error(f"unknown styles {', '.join(unknown)}; known: {', '.join(styles_available())}")
    out = Path(args.out)
    rows = [(style, row(run_style(style, args.robot, args.trials, args.jobs, out))) for style in styles]
    print(f"\n{args.robot}: whole-task success per program (median wall seconds of a trial)\n")
    print("| style | " + " | ".join(TASKS) + " | all |")
    print("|---" * (len(TASKS) + 2) + "|")
    for style, (cells, passed, total) in rows:
        print(f"| {style} | " + " | ".join(cells) + f" | {passed}/{total} |")


if __name__ == "__main__":
    main()
