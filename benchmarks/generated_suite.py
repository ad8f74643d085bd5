"""The generated benchmark under one policy, summarised per template family: whole-task success with its 95%
Wilson interval, the finished-steps ratio, and the median and total wall time of a trial.

Run: python benchmarks/generated_suite.py [--policy reference] [--robot panda] [--trials 3] [--jobs 2]
                                          [--out out/generated_<policy>_<robot>] [--read-only]

The run is ``roboscript bench --suite generated`` into ``--out`` (an interrupted run resumes; a finished one is
only read; with ``--read-only`` nothing is run). Wall times depend on what else the machine does: they are
figures, not assertions.
"""

from __future__ import annotations

import argparse
import re
import statistics
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

from roboscript.bench.results import read_records
from roboscript.bench.stats import wilson_interval
from roboscript.bench.tasks import load_suite


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--policy", default="reference")
    parser.add_argument("--robot", default="panda", choices=["panda", "ur5e"])
    parser.add_argument("--trials", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--suite", default="generated")
    parser.add_argument("--out", default=None)
    parser.add_argument("--read-only", action="store_true", help="summarise --out without running anything")
    args = parser.parse_args()
    safe = re.sub(r"[^A-Za-z0-9._-]+", "_", args.policy)
    out = Path(args.out or f"out/generated_{safe}_{args.robot}")
    if not args.read_only:
        command = [sys.executable, "-m", "roboscript.cli", "bench", "--suite", args.suite, "--policy", args.policy]
        command += ["--robot", args.robot, "--trials", str(args.trials), "--jobs", str(args.jobs), "--out", str(out)]
        subprocess.run(command, check=False)
    tasks = load_suite(args.suite)
    by_family: dict[str, list] = defaultdict(list)
    for record in read_records(out / "results.jsonl"):
        by_family[tasks[record.task].label].append(record)
    print("| family | tasks | trials | whole-task success [95% CI] | finished steps | median wall s | wall s |")
    print("|---|---|---|---|---|---|---|")
    everything = []
    for family in sorted(by_family):
        print(_row(family, by_family[family]))
        everything += by_family[family]
    print(_row("all", everything))
    return 0


def _row(label: str, records: list) -> str:
    wins = sum(r.ok and r.success for r in records)
    low, high = wilson_interval(wins, len(records))
    steps = statistics.mean(r.passed / len(r.checks) for r in records)
    walls = [r.wall_time_s for r in records]
    tasks = len({r.task for r in records})
    rate = f"{wins / len(records):.2f} [{low:.2f}, {high:.2f}] ({wins}/{len(records)})"
    wall = f"{statistics.median(walls):.1f} | {sum(walls):.0f}"
    return f"| {label} | {tasks} | {len(records)} | {rate} | {steps:.2f} | {wall} |"


if __name__ == "__main__":
    sys.exit(main())
