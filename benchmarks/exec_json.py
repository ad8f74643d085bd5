"""``roboscript exec PROGRAM --json`` prints one JSON document on stdout, whatever the program or the tools print:
every program of the prompt-only corpus, one trial each, its stdout read as JSON.

Run: python benchmarks/exec_json.py [--robot panda] [--perception gt] [--jobs 2] [--styles concise,...]
                                    [--out out/exec_json.jsonl]

One line per program is appended to ``--out`` as each run ends (an interrupted run resumes where it stopped): the
program, exec's exit code, whether stdout was one JSON document, and the task's whole-task success from it. Prints
how many programs gave readable JSON and lists those that did not, with the start of what they printed; exits 1
where any did not.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "data" / "prompt_corpus"


def programs(styles: list[str]) -> list[tuple[str, str, Path]]:
    """``(suite, task, file)`` of every program of the chosen styles."""
    return [
        (suite.name, path.stem, path)
        for style in styles
        for suite in sorted((CORPUS / style).iterdir())
        if suite.is_dir()
        for path in sorted(suite.glob("*.py"))
    ]


def exec_json(suite: str, task: str, path: Path, robot: str, perception: str) -> dict:
    """Runs one program through ``roboscript exec --json``; what came of reading its stdout as JSON."""
    command = [sys.executable, "-m", "roboscript.cli", "exec", str(path), "--task", task, "--suite", suite]
    command += ["--robot", robot, "--perception", perception, "--trials", "1", "--json"]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    record = {"program": str(path.relative_to(CORPUS)), "exit_code": done.returncode}
    try:
        document = json.loads(done.stdout)
    except json.JSONDecodeError as exc:
        return {**record, "json": False, "why": str(exc), "stdout_start": done.stdout[:300]}
    return {**record, "json": True, "whole_task_success": document.get("whole_task_success")}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robot", default="panda")
    parser.add_argument("--perception", default="gt")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--styles", default=",".join(sorted(p.name for p in CORPUS.iterdir() if p.is_dir())))
    parser.add_argument("--out", default="out/exec_json.jsonl")
    args = parser.parse_args()
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    done = {}
    if out.exists():
        done = {r["program"]: r for r in map(json.loads, out.read_text().splitlines()) if r}
    todo = [p for p in programs([s for s in args.styles.split(",") if s]) if str(p[2].relative_to(CORPUS)) not in done]
    print(f"{len(done)} programs done before, {len(todo)} to run", flush=True)
    with ThreadPoolExecutor(args.jobs) as pool, out.open("a") as sink:
        runs = pool.map(lambda p: exec_json(*p, args.robot, args.perception), todo)
        for k, record in enumerate(runs, 1):
            sink.write(json.dumps(record) + "\n")
            sink.flush()
            done[record["program"]] = record
            print(f"[{k}/{len(todo)}] {record['program']}: json {record['json']}", flush=True)
    unreadable = [r for r in done.values() if not r["json"]]
    print(f"\n{len(done) - len(unreadable)} of {len(done)} programs printed one JSON document on stdout")
    for r in unreadable:
        print(f"  {r['program']}: {r['why']}; stdout began {r['stdout_start']!r}")
    return 1 if unreadable else 0


if __name__ == "__main__":
    sys.exit(main())
