"""What the sandbox costs: starting a program's process, and one tool call, in milliseconds (medians).

    .venv/bin/python benchmarks/sandbox_calls.py [--repeats 7] [--calls 500]

A program that calls nothing measures the start (and end) of a program's process; one that calls a tool ``--calls``
times, less that, divided by the calls, measures a tool call's round trip with its arguments and answer (a pose, a
name list, an array). Run it on the same machine before and after a change to compare.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from roboscript.api import Pose
from roboscript.codegen.program_process import run_program
from roboscript.codegen.sandbox import Limits


def pose_of(name):
    return Pose([0.5, 0.0, 0.2], [0.0, 0.0, 0.0, 1.0])


def names():
    return ["apple", "footed_bowl", "cabinet.drawer_0", "cabinet.handle_0"]


def box(name):
    return np.array([0.1, 0.2, 0.0, 0.2, 0.3, 0.1])


NAMESPACE = {"get_object_pose": pose_of, "get_object_name_list": names, "get_3d_bbox": box, "Pose": Pose}
TOOLS = ("get_object_pose", "get_object_name_list", "get_3d_bbox")


def timed_run(program: str) -> float:
    started = time.perf_counter()
    result = run_program(program, NAMESPACE, Limits(timeout=120), forwarded=TOOLS)
    elapsed = time.perf_counter() - started
    if result.error is not None:
        raise SystemExit(f"the benchmark's program failed: {result.error}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--calls", type=int, default=500)
    args = parser.parse_args()
    calls = (
        f"for i in range({args.calls}):\n"
        "    p = get_object_pose('apple')\n    n = get_object_name_list()\n    b = get_3d_bbox('apple')\n"
    )
    empty = [timed_run("x = 1") for _ in range(args.repeats)]
    busy = [timed_run(calls) for _ in range(args.repeats)]
    start_ms = statistics.median(empty) * 1000
    per_call_ms = (statistics.median(busy) - statistics.median(empty)) / (3 * args.calls) * 1000
    print(f"program process start and end: median {start_ms:.1f} ms (min {min(empty) * 1000:.1f}, n={len(empty)})")
    print(f"one tool call (pose, names, box; round trip): median {per_call_ms:.3f} ms over {3 * args.calls} calls")


if __name__ == "__main__":
    main()
