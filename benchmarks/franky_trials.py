"""Trials through libfranka against franky-sim beside the same trials on the MuJoCo backend: the gap a real protocol
and another simulator's arm make, with the FR3 and full perception on both sides.

Per task (default simple_0 and moderate_2) it runs the task's reference program and a program written from the
prompt alone (``tests/data/prompt_corpus/concise/paper/<task>.py``), for seeds 0..N-1: through franky-sim
(``backend="franky"``: :mod:`roboscript.bench.franky_trial`, the FR3 at speed scale 0.05) and on the MuJoCo backend
(the same seed's layout, the FR3, the default speed scale). Results go to ``--out`` (a JSONL file) as they come;
a rerun skips what is there. Prints whole-task success per task, program and backend, and the wall time per trial
(medians). Figures, never assertions; franky-sim runs in real time, so each of its trials takes a minute or more.

    python benchmarks/franky_trials.py --trials 5 --out out/franky_sim.jsonl
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from collections import defaultdict
from pathlib import Path

from roboscript.bench.tasks import get_task
from roboscript.bench.trial import TrialSpec, run_trial

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "data" / "prompt_corpus" / "concise" / "paper"


def programs(task_id: str) -> dict[str, str]:
    found = {"reference": get_task(task_id).reference_program()}
    written = CORPUS / f"{task_id}.py"
    if written.exists():
        found["prompt-only"] = written.read_text()
    return found


def run_one(task_id: str, label: str, program: str, backend: str, seed: int) -> dict:
    started = time.monotonic()
    kind = "franky" if backend == "franky-sim" else "mujoco"
    try:
        record = run_trial(TrialSpec(task_id, "fr3", seed, seed, program, perception="full", backend=kind))
        success, error = record.success, record.error
    except Exception as exc:  # a trial that could not even be judged (the arm lost) is a failed trial, not the end
        success, error = False, f"{type(exc).__name__}: {exc}"
    return {
        "task": task_id,
        "program": label,
        "backend": backend,
        "seed": seed,
        "success": success,
        "error": (error or "")[:300],
        "wall": time.monotonic() - started,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tasks", default="simple_0,moderate_2")
    parser.add_argument("--trials", type=int, default=5)
    parser.add_argument("--out", default="out/franky_sim.jsonl")
    args = parser.parse_args()
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    done = [json.loads(line) for line in out.read_text().splitlines()] if out.exists() else []
    seen = {(r["task"], r["program"], r["backend"], r["seed"]) for r in done}
    for task_id in args.tasks.split(","):
        for label, program in programs(task_id).items():
            for seed in range(args.trials):
                for backend in ("franky-sim", "mujoco"):
                    if (task_id, label, backend, seed) in seen:
                        continue
                    row = run_one(task_id, label, program, backend, seed)
                    done.append(row)
                    with out.open("a") as stream:
                        stream.write(json.dumps(row) + "\n")
                    said = "ok" if row["success"] else row["error"] or "checks failed"
                    print(f"{task_id} {label} {backend} seed {seed}: {said} ({row['wall']:.0f} s)", flush=True)
    table: dict[tuple[str, str], dict[str, list]] = defaultdict(lambda: defaultdict(list))
    for row in done:
        table[(row["task"], row["program"])][row["backend"]].append(row)
    print("\n| task | program | through franky-sim | on the MuJoCo backend | median wall, franky-sim / MuJoCo (s) |")
    print("|---|---|---|---|---|")
    for (task_id, label), by_backend in sorted(table.items()):
        cells = []
        for backend in ("franky-sim", "mujoco"):
            rows = by_backend.get(backend, [])
            cells.append(f"{sum(r['success'] for r in rows)}/{len(rows)}")
        walls = [
            f"{statistics.median(r['wall'] for r in by_backend[b]):.0f}" if by_backend.get(b) else "-"
            for b in ("franky-sim", "mujoco")
        ]
        print(f"| {task_id} | {label} | {cells[0]} | {cells[1]} | {' / '.join(walls)} |")


if __name__ == "__main__":
    main()
