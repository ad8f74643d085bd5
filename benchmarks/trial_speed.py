"""Where a benchmark trial's wall time goes, and its ratio to the time spent stepping the physics.

Each trial runs as the benchmark's runner runs it: for code with trial workers (``roboscript.bench.workers``),
forked from one worker kept across the run (what it makes for a world's first trial serves the next: its time is
the ``elapsed`` beyond ``wall`` in the results file, not a trial's wall time); for older code, in a fresh process
that has imported the tools and, where the code has one, warmed its caches with ``roboscript.bench.warm``.
``mujoco.mj_step`` is wrapped to time the physics. Per task and perception mode the medians are printed: wall time,
physics time, their ratio, and (for code that marks them, see ``roboscript.phases``) the time spent building,
rendering, perceiving, searching grasps and placements, in IK, planning, physics and the rest.

With ``--baseline REV`` the same trials also run on that git revision's code (checked out in a temporary worktree)
in the same run, each trial of the baseline right before the same trial of the current code, so that both meet
the same machine. Results are appended to ``--out`` as they come, and a rerun skips what is there. Nothing is
asserted: the figures are printed.

    python benchmarks/trial_speed.py --modes gt --trials 2 --baseline cef2b00
    python benchmarks/trial_speed.py --modes gt,gt-2d,full --tasks hard_0,hard_1
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

from roboscript.phases import PHASES as MARKED_PHASES

REPO = Path(__file__).resolve().parents[1]
PHASES = (*MARKED_PHASES, "rest")

# Run in the child, with the tree under test first on the path.
CHILD = r"""
import importlib, json, sys, time
import roboscript  # chooses the GL backend before MuJoCo is imported
try:
    importlib.import_module("roboscript.bench.warm")  # what the runner's fork server does, where it exists
except ImportError:
    pass
from roboscript.bench.tasks import get_task
from roboscript.bench.trial import TrialSpec, run_trial
from _timed_trial import stepping_timed

task, robot, seed, mode = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
program = get_task(task).reference_program()
started = time.perf_counter()
record, stepping = stepping_timed(lambda: run_trial(TrialSpec(task, robot, seed, seed, program, perception=mode)))
wall = time.perf_counter() - started
print("RESULT " + json.dumps({"success": record.success, "outcome": record.outcome, "sim": record.sim_time_s,
                              "wall": wall, "stepping": stepping, "phases": getattr(record, "phases", {})}))
"""


# A driver for code that has trial workers (roboscript.bench.workers): trials run as the benchmark's runner runs
# them, each forked from a worker kept across them (one job), the stepping timed by _timed_trial.run.
DRIVER = r"""
import json, sys, time
import roboscript  # chooses the GL backend before MuJoCo is imported
from roboscript.bench.runner import TrialPool
from roboscript.bench.tasks import get_task
from roboscript.bench.trial import TrialSpec
import _timed_trial

with TrialPool(1, serve_args=(_timed_trial.run,)) as pool:
    for line in sys.stdin:
        task, robot, seed, mode = line.split()
        spec = TrialSpec(task, robot, int(seed), int(seed), get_task(task).reference_program(), perception=mode)
        started = time.perf_counter()
        (record,) = pool.run([spec])
        elapsed = time.perf_counter() - started
        phases = dict(record.phases)
        print("RESULT " + json.dumps({"success": record.success, "outcome": record.outcome, "sim": record.sim_time_s,
                                      "wall": phases.pop("wall", record.wall_time_s), "elapsed": elapsed,
                                      "stepping": phases.pop(_timed_trial.STEPPING, 0.0), "phases": phases,
                                      "error": record.error}), flush=True)
"""


class Runner:
    """Runs one code tree's trials: in a fresh process each (code without trial workers, as its runner did), or
    through one driver process that keeps a trial worker across them (code with workers, as its runner does)."""

    def __init__(self, source: Path):
        self.source = source
        self.pooled = (source / "roboscript" / "bench" / "workers.py").exists()
        self.env = dict(os.environ, PYTHONPATH=f"{source}{os.pathsep}{Path(__file__).parent}")
        self.driver = None

    def run(self, task: str, robot: str, seed: int, mode: str) -> dict:
        if not self.pooled:
            done = subprocess.run(
                [sys.executable, "-c", CHILD, task, robot, str(seed), mode],
                env=self.env,
                capture_output=True,
                text=True,
            )
            lines = done.stdout.splitlines()
            problem = done.stderr[-2000:]
        else:
            if self.driver is None:
                self.driver = subprocess.Popen(
                    [sys.executable, "-c", DRIVER], env=self.env, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                    text=True,
                )  # fmt: skip
            self.driver.stdin.write(f"{task} {robot} {seed} {mode}\n")
            self.driver.stdin.flush()
            lines = [self.driver.stdout.readline()]
            problem = "the driver stopped; its errors are above"
        for line in lines:
            if line.startswith("RESULT "):
                return json.loads(line[len("RESULT ") :])
        raise RuntimeError(f"{task} seed {seed} ({mode}) on {self.source} failed:\n{problem}")

    def close(self) -> None:
        if self.driver is not None:
            self.driver.stdin.close()
            self.driver.wait(60)


def _key(r: dict) -> tuple:
    return (r["code"], r["mode"], r["task"], r["seed"])


def measure(args: argparse.Namespace, out: Path) -> list[dict]:
    done = {}
    if out.exists():
        for line in out.read_text().splitlines():
            try:
                r = json.loads(line)
            except json.JSONDecodeError:  # a line cut short by an interruption
                continue
            done[_key(r)] = r
    trees = {"current": REPO / "src"}
    worktree = None
    if args.baseline:
        worktree = Path(tempfile.mkdtemp(prefix="trial_speed_baseline_"))
        subprocess.run(
            ["git", "-C", str(REPO), "worktree", "add", "-f", "--detach", str(worktree), args.baseline],
            check=True,
            capture_output=True,
        )
        trees = {f"baseline {args.baseline}": worktree / "src", **trees}
    runners = {code: Runner(source) for code, source in trees.items()}
    try:
        with out.open("a") as sink:
            for mode in args.modes.split(","):
                for task in args.tasks.split(","):
                    for seed in range(args.trials):
                        for code, runner in runners.items():
                            key = (code, mode, task, seed)
                            if key in done:
                                continue
                            result = {"code": code, "mode": mode, "task": task, "seed": seed}
                            result.update(runner.run(task, args.robot, seed, mode))
                            sink.write(json.dumps(result) + "\n")
                            sink.flush()
                            done[key] = result
                            ratio = result["wall"] / max(result["stepping"], 1e-9)
                            print(
                                f"{code:>18} {mode:>6} {task:>10} seed {seed}: wall {result['wall']:6.1f} s, "
                                f"physics {result['stepping']:5.1f} s, ratio {ratio:4.1f}, "
                                f"{'ok' if result['success'] else result['outcome']}",
                                flush=True,
                            )
    finally:
        for runner in runners.values():
            runner.close()
        if worktree is not None:
            subprocess.run(
                ["git", "-C", str(REPO), "worktree", "remove", "--force", str(worktree)], capture_output=True
            )
    return list(done.values())


def report(results: list[dict]) -> str:
    groups: dict[tuple, list[dict]] = defaultdict(list)
    for r in results:
        groups[(r["mode"], r["code"])].append(r)
    lines = []
    for (mode, code), rs in sorted(groups.items()):
        lines.append(f"\n## {mode}, {code}: {len(rs)} trials, {sum(r['success'] for r in rs)} succeeded")
        lines.append("| task | wall s | physics s | wall/physics | " + " | ".join(PHASES) + " |")
        lines.append("|---" * (4 + len(PHASES)) + "|")
        by_task: dict[str, list[dict]] = defaultdict(list)
        for r in rs:
            by_task[r["task"]].append(r)
        for task in [*sorted(by_task), "all"]:
            chosen = rs if task == "all" else by_task[task]
            wall = statistics.median(r["wall"] for r in chosen)
            physics = statistics.median(r["stepping"] for r in chosen)
            ratio = statistics.median(r["wall"] / max(r["stepping"], 1e-9) for r in chosen)
            phases = [
                f"{statistics.median(r['phases'].get(p, 0.0) for r in chosen):.2f}" if chosen[0]["phases"] else "-"
                for p in PHASES
            ]
            name = "**median, all**" if task == "all" else task
            lines.append(f"| {name} | {wall:.1f} | {physics:.2f} | {ratio:.1f} | " + " | ".join(phases) + " |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tasks", default="simple_0,simple_1,moderate_0,moderate_1,moderate_2,hard_0,hard_1,hard_2")
    parser.add_argument("--modes", default="gt", help="comma-separated perception modes")
    parser.add_argument("--robot", choices=["panda", "ur5e"], default="panda")
    parser.add_argument("--trials", type=int, default=1, help="seeds per task (0, 1, ...)")
    parser.add_argument("--baseline", default=None, help="a git revision to measure beside the current code")
    parser.add_argument("--out", default="out/trial_speed.jsonl")
    args = parser.parse_args()
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    print(report(measure(args, out)))


if __name__ == "__main__":
    main()
