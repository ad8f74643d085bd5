"""The benchmark's reference programs through ROS against the MuJoCo backend: whole-task success per task side by
side, the gap, and the wall-time overhead of a trial through ROS (medians).

Runs (or resumes) both benchmarks with `roboscript bench`, the MuJoCo one in gt-2d (the camera pipeline with the
simulator's segmentation: what a ROS trial gets from the segmentation topic), then prints the comparison; or, given
two run directories, only compares them. Nothing is asserted: the figures are printed.

    python benchmarks/ros_vs_mujoco.py --robot panda --trials 10 --out out/ros_vs_mujoco
    python benchmarks/ros_vs_mujoco.py --compare RUN_ROS RUN_MUJOCO
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

GAP = 0.10  # the acceptance's bound on the gap of whole-task success, per task


def _records(run: Path) -> list[dict]:
    lines = (run / "results.jsonl").read_text().splitlines()
    records = []
    for line in lines:
        try:
            records.append(json.loads(line))
        except json.JSONDecodeError:  # a line cut short by an interruption
            continue
    return records


def _success(records: list[dict]) -> dict[str, tuple[int, int]]:
    by_task: dict[str, tuple[int, int]] = {}
    for r in records:
        done, total = by_task.get(r["task"], (0, 0))
        passed = bool(r["checks"]) and all(c["passed"] for c in r["checks"])
        by_task[r["task"]] = (done + passed, total + 1)
    return by_task


def compare(ros: Path, mujoco: Path) -> str:
    a, b = _records(ros), _records(mujoco)
    sa, sb = _success(a), _success(b)
    lines = ["| Task | ROS | MuJoCo gt-2d | Gap |", "|---|---|---|---|"]
    for task in sorted(set(sa) | set(sb)):
        (pa, na), (pb, nb) = sa.get(task, (0, 0)), sb.get(task, (0, 0))
        ra, rb = (pa / na if na else float("nan")), (pb / nb if nb else float("nan"))
        gap = abs(ra - rb)
        flag = "" if gap <= GAP + 1e-9 else f" (over {GAP:.2f})"
        lines.append(f"| {task} | {ra:.2f} ({pa}/{na}) | {rb:.2f} ({pb}/{nb}) | {gap:.2f}{flag} |")
    wa = statistics.median(r["wall_time_s"] for r in a)
    wb = statistics.median(r["wall_time_s"] for r in b)
    lines.append("")
    lines.append(f"median trial wall time: ROS {wa:.1f} s, MuJoCo {wb:.1f} s; overhead {wa / wb:.2f}x")
    errors = [f"{r['task']} trial {r['trial']}: {r['error']}" for r in a + b if r.get("error")]
    if errors:
        lines.append("errors:")
        lines += [f"  {e[:200]}" for e in errors]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robot", choices=["panda", "ur5e"], default="panda")
    parser.add_argument("--trials", type=int, default=10)
    parser.add_argument("--tasks", default=None, help="comma-separated task ids; default: all")
    parser.add_argument("--out", default="out/ros_vs_mujoco")
    parser.add_argument("--compare", nargs=2, metavar=("RUN_ROS", "RUN_MUJOCO"), default=None)
    args = parser.parse_args()
    if args.compare:
        print(compare(Path(args.compare[0]), Path(args.compare[1])))
        return
    out = Path(args.out)
    runs = {"ros": ["--backend", "ros"], "mujoco": ["--perception", "gt-2d"]}
    for name, flags in runs.items():
        command = [sys.executable, "-m", "roboscript.cli", "bench", "--policy", "reference", "--robot", args.robot]
        command += ["--trials", str(args.trials), "--out", str(out / f"{name}_{args.robot}"), *flags]
        command += ["--tasks", args.tasks] if args.tasks else []
        subprocess.run(command, check=True)
    print(compare(out / f"ros_{args.robot}", out / f"mujoco_{args.robot}"))


if __name__ == "__main__":
    main()
