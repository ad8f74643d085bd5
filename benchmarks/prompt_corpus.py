"""The prompt-only corpus as a benchmark: programs written by authors who saw only what an LLM sees (the system
prompt, the tool doc-strings, the few-shot examples and a task's query), per template family and paper task, per
arm and perception mode.

Run: python benchmarks/prompt_corpus.py [--robots panda,ur5e] [--perception gt,full] [--trials 10] [--jobs 2]
                                        [--styles concise,...] [--suites generated,paper] [--out out/prompt_corpus]

``tests/data/prompt_corpus/<style>/<suite>/<task_id>.py``: each style and suite runs as ``roboscript bench --suite
<suite> --policy programs:<folder>`` into ``<out>/<robot>_<perception>/<style>_<suite>``, a run directory: an
interrupted run resumes where it stopped, a finished one is only read. Prints whole-task success per family (the
task's label) and per paper task, for each arm and mode, then the failed trials' first errors. Figures, never
assertions; run two at once to see them under load.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "data" / "prompt_corpus"


def folders(styles: list[str], suites: list[str] | None = None) -> list[tuple[str, str, Path]]:
    """``(style, suite, folder)`` of every folder of programs of the chosen styles (and suites: all by default)."""
    out = []
    for style in styles:
        for suite_folder in sorted((CORPUS / style).iterdir()):
            if suites is not None and suite_folder.name not in suites:
                continue
            if suite_folder.is_dir() and any(suite_folder.glob("*.py")):
                out.append((style, suite_folder.name, suite_folder))
    return out


ROOT = CORPUS.parents[2]


def run(folder: Path, suite: str, robot: str, perception: str, trials: int, jobs: int, out: Path) -> Path:
    """Runs (or resumes) one folder's programs; returns the run directory. The policy names the folder from the
    checkout's root, so that a run directory copied to another machine or checkout resumes there."""
    tasks = ",".join(sorted(p.stem for p in folder.glob("*.py")))
    policy = f"programs:{folder.relative_to(ROOT)}"
    command = [sys.executable, "-m", "roboscript.cli", "bench", "--suite", suite, "--policy", policy]
    command += ["--tasks", tasks, "--robot", robot, "--perception", perception, "--trials", str(trials)]
    command += ["--jobs", str(jobs), "--out", str(out.resolve())]
    subprocess.run(command, check=False, stdout=subprocess.DEVNULL, cwd=ROOT)
    return out


def records(directory: Path) -> list[dict]:
    results = directory / "results.jsonl"
    lines = results.read_text().splitlines() if results.exists() else []
    return [json.loads(line) for line in lines if line.strip()]


def group_of(task: str) -> str:
    """A generated task's family (``swap.gen_004`` -> swap); a paper task is its own group."""
    return task.split(".")[0]


def passed(record: dict) -> bool:
    return bool(record["checks"]) and all(c["passed"] for c in record["checks"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robots", default="panda,ur5e")
    parser.add_argument("--perception", default="gt")
    parser.add_argument("--trials", type=int, default=10)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--styles", default=",".join(sorted(p.name for p in CORPUS.iterdir() if p.is_dir())))
    parser.add_argument("--suites", default="generated,paper", help="the corpus's suites to run: generated, paper")
    parser.add_argument("--out", default="out/prompt_corpus")
    args = parser.parse_args()
    suites = [s for s in args.suites.split(",") if s]
    if not suites or set(suites) - {"generated", "paper"}:
        parser.error(f"--suites takes generated, paper or both (comma-separated), got {args.suites!r}")
    styles = [s for s in args.styles.split(",") if s]
    unknown = [s for s in styles if not (CORPUS / s).is_dir()]
    if unknown:
        parser.error(f"unknown styles {', '.join(unknown)}; known: {', '.join(p.name for p in CORPUS.iterdir())}")
    failures: list[str] = []
    for robot in args.robots.split(","):
        for mode in args.perception.split(","):
            tally: dict[str, list[int]] = defaultdict(lambda: [0, 0])
            for style, suite, folder in folders(styles, suites):
                directory = Path(args.out) / f"{robot}_{mode}" / f"{style}_{suite}"
                run(folder, suite, robot, mode, args.trials, args.jobs, directory)
                for record in records(directory):
                    cell = tally[group_of(record["task"])]
                    cell[0] += passed(record)
                    cell[1] += 1
                    if not passed(record):
                        error = (record.get("error") or "checks failed")[:200]
                        failures.append(f"{robot} {mode} {style}/{record['task']} seed {record['seed']}: {error}")
            total = [sum(c[0] for c in tally.values()), sum(c[1] for c in tally.values())]
            print(f"\n{robot}, {mode}: whole-task success per family or paper task (trials passed / run)\n")
            print("| group | success | trials |\n|---|---|---|")
            for group in sorted(tally):
                ok, n = tally[group]
                print(f"| {group} | {ok / n:.2f} | {ok}/{n} |")
            print(f"| all | {total[0] / max(total[1], 1):.2f} | {total[0]}/{total[1]} |")
    print(f"\n{len(failures)} failed trials" + (":" if failures else ""))
    for line in failures:
        print(" ", line)


if __name__ == "__main__":
    main()
