"""The command line's sweeps and studies: ``roboscript sweep SWEEP.yaml`` and ``roboscript study NAME``."""

from __future__ import annotations

import argparse
import re
import time
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the command line imports what a command runs when it runs: --help starts in a fraction of a second
    from roboscript.study.sweep import Executor


def _names(text: str) -> list[str]:
    names = [n.strip() for n in text.split(",") if n.strip()]
    if not names:
        raise argparse.ArgumentTypeError(f"expected comma-separated names, got {text!r}")
    return names


def _robots(text: str) -> list[str]:
    from roboscript.robots import ROBOTS

    names = ["panda", "ur5e"] if text == "both" else _names(text)
    for name in names:
        if name not in ROBOTS:
            raise argparse.ArgumentTypeError(f"unknown robot {name!r}; robots: {', '.join(sorted(ROBOTS))} (or both)")
    return names


def make_executor(args: argparse.Namespace) -> Executor:
    """A local process pool of ``--jobs``, or Ray with ``--ray [ADDRESS]``."""
    if args.ray is not None:
        from roboscript.study.ray_executor import RayExecutor

        return RayExecutor(None if args.ray == "local" else args.ray, args.jobs)
    from roboscript.bench.runner import default_jobs
    from roboscript.study.sweep import LocalExecutor

    return LocalExecutor(args.jobs or default_jobs())


def _close(executor: Executor) -> None:
    close = getattr(executor, "close", None)
    if close is not None:
        close()


def cmd_sweep(args: argparse.Namespace) -> int:
    from roboscript.study.sweep import run_sweep
    from roboscript.study.sweep_file import load_sweep_file

    sweep = load_sweep_file(args.sweep_file)
    out = Path(args.out or f"out/sweeps/{re.sub(r'[^A-Za-z0-9._-]+', '_', sweep.name)}")
    executor = make_executor(args)
    started = time.perf_counter()
    try:
        runs = run_sweep(sweep, out, executor, progress=True)
    finally:
        _close(executor)
    from roboscript.bench.compare import compare_runs
    from roboscript.cli.trial_output import throughput

    print(compare_runs([r.directory.path for r in runs], "whole_task_success"))
    ran = sum(len(r.pending) for r in runs)
    if ran:
        print(throughput(ran, time.perf_counter() - started, getattr(executor, "jobs", None)))
    print(f"results in {out} ({len(runs)} runs); `roboscript report {out}` draws them")
    return 0


def cmd_study(args: argparse.Namespace) -> int:
    from roboscript.study.run import run_study, study_sweep

    sweep = study_sweep(
        args.study,
        args.robot,
        args.trials,
        args.seed,
        args.template,
        args.objects,
        args.grasp,
        args.timeout,
        args.videos,
    )
    out = Path(args.out or f"out/study/{args.study}")
    executor = make_executor(args)
    try:
        outcome = run_study(sweep, out, executor)
    finally:
        _close(executor)
    print((out / "study.md").read_text())
    print(f"wall time {outcome.wall_time_s:.0f} s; files: {', '.join(str(p) for p in outcome.files)}")
    return 0


def _add_pool_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--jobs", type=int, default=None, help="trials at once (default: this machine's CPUs, or "
                        "with --ray the cluster's)")  # fmt: skip
    parser.add_argument(
        "--ray",
        nargs="?",
        const="local",
        default=None,
        metavar="ADDRESS",
        help="run on Ray: a cluster's address (auto, HOST:PORT), or without one a local cluster of --jobs CPUs",
    )
    parser.add_argument("--out", default=None, help="output folder (resumed when it holds an earlier run)")


def add_study_commands(sub) -> None:
    """``sweep`` and ``study`` on the ``roboscript`` parser's subcommands."""
    from roboscript.bench.results import VIDEO_CHOICES

    sweep = sub.add_parser("sweep", help="run a sweep file: tasks x trials x policies x robots x perception modes")
    sweep.add_argument("sweep_file", help="a sweep file (YAML or JSON; see roboscript.study.sweep_file)")
    _add_pool_options(sweep)
    sweep.set_defaults(func=cmd_sweep)

    study = sub.add_parser("study", help="a study over the object library (the object-shape study: objects)")
    study.add_argument("study", help="a packaged study (objects) or a study file")
    study.add_argument("--template", type=_names, default=None, help="comma-separated templates (default: all)")
    study.add_argument("--objects", type=_names, default=None, help="comma-separated object types (default: all)")
    study.add_argument(
        "--grasp", type=_names, default=None, help="comma-separated grasp tools: adaptive, central, horizontal"
    )
    study.add_argument(
        "--robot", type=_robots, default=["panda"], help="panda, ur5e, fr3, both (panda and ur5e), or a comma list"
    )
    study.add_argument("--trials", type=int, default=10, help="trials per cell (template x object x grasp tool)")
    study.add_argument("--seed", type=int, default=0, help="trial i uses seed + i for the world's randomisation")
    study.add_argument("--timeout", type=float, default=300.0, help="time limit of one program, wall seconds")
    study.add_argument(
        "--videos", choices=VIDEO_CHOICES, default="none", help="record trials' videos (kept: failed/all)"
    )
    _add_pool_options(study)
    study.set_defaults(func=cmd_study)
