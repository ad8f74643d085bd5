"""Running programs and reporting them: ``exec``, ``run`` (an LLM writes the program), ``bench``, ``demo``,
``report``."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from roboscript.cli.options import (
    RECORD_HELP,
    ROBOT_NAMES,
    add_perception_option,
    add_run_options,
    add_suite_option,
    rounds,
    seconds,
)
from roboscript.cli.trial_output import (
    EXIT_STATUS_HELP,
    SUCCESS,
    TASK_FAILED,
    USAGE,
    exit_code,
    files_written,
    llm_unreachable,
    output_lines,
    print_refusal,
    print_result,
    stage_printer,
    throughput,
)
from roboscript.errors import InvalidArgumentError


def _trial_options(args: argparse.Namespace, instruction: str | None) -> dict:
    """What ``exec`` and ``run`` tell each of their trials, from their shared options."""
    return {
        "robot": args.robot,
        "trials": args.trials,
        "seed": args.seed,
        "timeout": args.timeout,
        "video": args.video,
        "instruction": instruction,
        "world": args.world,
        "perception": args.perception,
        "suite": args.suite,
        "backend": args.backend,
        "robot_config": args.robot_config,
        "record": args.record,
    }


def cmd_exec(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import trial_specs
    from roboscript.bench.metrics import task_result
    from roboscript.bench.progress import progress_printer
    from roboscript.bench.runner import run_isolated
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.cli.robot import robot_requested, run_on_running_robot
    from roboscript.codegen.execute import static_refusal

    scene = args.world or get_task(args.task, args.suite).world
    path = Path(args.program)
    if path.is_dir():
        raise InvalidArgumentError(f"{str(path)!r} is a folder; give the program's file (a .py file)")
    if not path.is_file():
        raise InvalidArgumentError(f"no program file {str(path)!r}")
    program = path.read_text()
    label = free_task(args.world, "run the program").id if args.world else args.task
    refusal = static_refusal(program)  # said once, here, rather than once for each trial
    if refusal is not None:
        if args.json:  # the same document as a run's, with no trial, and why none ran
            none_ran = {**task_result(label, args.robot, []), "checked": not args.world}
            print(json.dumps({**none_ran, "outcome": refusal.outcome.value, "error": refusal.error}))
        else:
            print_refusal(str(path), refusal)
        return TASK_FAILED
    if robot_requested(args):
        return run_on_running_robot(args, program, scene)
    specs = trial_specs(label, program, **_trial_options(args, "run the program" if args.world else None))
    records = run_isolated(specs, args.jobs, None if args.json else progress_printer(len(specs)))
    result = task_result(label, args.robot, records)
    checked = not args.world
    if args.json:
        print(json.dumps({**result, "checked": checked}))
    else:
        print_result(result, checked, files_written(specs))
    return exit_code(records, checked)


def cmd_bench(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import default_out, folder_label, run_benchmark

    tasks = [t.strip() for t in args.tasks.split(",") if t.strip()] if args.tasks else None
    if args.repair and not args.policy.startswith("llm:"):
        raise InvalidArgumentError("--repair needs an LLM policy (--policy llm:SPEC)")
    out = args.out or default_out(
        folder_label(args.policy, args.repair), args.robot, args.perception, args.suite, args.backend
    )
    result = run_benchmark(
        args.policy,
        tasks,
        args.robot,
        args.trials,
        args.seed,
        out,
        args.jobs,
        args.timeout,
        progress=not args.json,
        repair_rounds=args.repair,
        perception=args.perception,
        suite=args.suite,
        backend=args.backend,
        robot_config=args.robot_config,
        videos=args.videos,
    )
    if args.json:
        print(json.dumps({"tasks": result["tasks"], "wall_time_s": result["wall_time_s"], "out": result["out"]}))
    else:
        print((Path(result["out"]) / "summary.md").read_text())
        kept = f"; videos in {Path(result['out']) / 'videos'}" if args.videos != "none" else ""
        if result["ran"] == 0:
            print(f"every trial was already recorded in {result['out']}: nothing ran (a new --out starts afresh)")
        else:
            print(throughput(result["ran"], result["wall_time_s"], args.jobs))
        print(f"wall time {result['wall_time_s']:.1f} s; results in {result['out']}{kept}")
        print(f"see each trial, its output and its video: roboscript report {result['out']}")
    return SUCCESS if all(t["whole_task_success"] == 1.0 for t in result["tasks"].values()) else TASK_FAILED


def cmd_run(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import trial_specs
    from roboscript.bench.metrics import task_result
    from roboscript.bench.runner import run_isolated
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.bench.trial import LLMAuthor
    from roboscript.cli.robot import robot_requested
    from roboscript.llm import make_llm
    from roboscript.sim.world_catalog import load_world

    if args.world:
        load_world(args.world)  # a bad world name or file fails here, before any LLM is asked
        label = free_task(args.world, args.instruction).id
    else:
        label = get_task(args.task, args.suite).id
    llm = make_llm(args.llm)  # fails here, clearly, when no LLM is configured
    if robot_requested(args):
        return _run_llm_on_robot(args, llm, label)
    specs = trial_specs(label, LLMAuthor(args.llm or llm.name, args.repair), **_trial_options(args, args.instruction))
    show = None if args.json else stage_printer()
    if show is not None:
        for spec in specs:
            show(spec, "starting its process")
    records = run_isolated(specs, args.jobs, on_stage=show)
    result = task_result(label, args.robot, records)
    checked = not args.world
    if args.json:
        print(json.dumps({**result, "checked": checked, "programs": [r.program for r in records]}))
        return _unless_llm_unreachable(records, exit_code(records, checked))
    for record in sorted(records, key=lambda r: r.trial):
        for i, attempt in enumerate(record.attempts[:-1]):
            print(f"trial {record.trial}, attempt {i + 1}: {attempt['outcome']}: {attempt['error']} (repaired)")
        if args.show_code and record.program is not None:
            print(f"trial {record.trial}, the program:\n{record.program}")
    print_result(result, checked, files_written(specs))
    return _unless_llm_unreachable(records, exit_code(records, checked))


def _unless_llm_unreachable(records, code: int) -> int:
    """A run whose LLM could not be asked at all is a usage error (a wrong address, key or model), not a task the
    robot failed: said once, on stderr, with :data:`USAGE`."""
    error = llm_unreachable(records)
    if error is None:
        return code
    print(f"roboscript: error: the LLM could not be asked, so no program ran: {error}", file=sys.stderr)
    return USAGE


def _run_llm_on_robot(args: argparse.Namespace, llm, label: str) -> int:
    """``run --master``: the LLM writes the program once, for the scene's names; it then runs as ``exec`` would."""
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.cli.robot import run_on_running_robot
    from roboscript.codegen.author import ProgramAuthor

    task = free_task(args.world, args.instruction) if args.world else get_task(args.task, args.suite)
    program = ProgramAuthor(llm, task.query_for(args.instruction)).program
    if args.show_code:
        print(program)
    return run_on_running_robot(args, program, task.world)


def cmd_demo(args: argparse.Namespace) -> int:
    from roboscript.bench.tasks import get_task
    from roboscript.demo import DemoPlan, run_demo
    from roboscript.llm.spec import configured_spec

    task = get_task(args.task, args.suite)
    plan = DemoPlan(task.id, args.robot, args.llm or configured_spec(), Path(args.out), args.suite)
    print(f'RoboScript demo: {task.id} on the {args.robot}: "{task.instruction}"')
    print(f"program: {plan.source}")
    if plan.llm is not None:
        from roboscript.llm import make_llm

        make_llm(plan.llm)  # a bad spec fails here, before the world is built
    record = run_demo(
        plan,
        seed=args.seed,
        timeout=args.timeout,
        repair_rounds=args.repair,
        perception=args.perception,
        backend=args.backend,
    )
    status = "task done" if record.success else "task NOT done"
    print(
        f"{status}: {record.outcome}, {record.passed}/{len(record.checks)} checks"
        + (f"; error: {record.error}" if record.error else "")
    )
    for line in output_lines(record.output, indent=""):
        print(line)
    print(f"simulated {record.sim_time_s:.1f} s in {record.wall_time_s:.1f} s wall")
    print(f"report: {plan.out / 'report.md'}; video: {plan.out / (task.id + '.mp4')}")
    return _unless_llm_unreachable([record], SUCCESS if record.success else TASK_FAILED)


def cmd_report(args: argparse.Namespace) -> int:
    from roboscript.report.write import write_report

    report = write_report(args.runs, args.out, args.metric)
    print(report.markdown)
    for note in report.notes:
        print(note, file=sys.stderr)
    runs = f"{len(report.runs)} run{'s' if len(report.runs) != 1 else ''}"
    print(f"report of {runs}: {', '.join(str(p) for p in report.files)}")
    return 0


VIDEO_HELP = "record camera_left into this MP4 file (with several trials, <stem>_trial<i>.mp4 each)"


def add_run_commands(sub) -> None:
    from roboscript.bench.metrics import METRICS
    from roboscript.bench.results import VIDEO_CHOICES
    from roboscript.cli.robot import add_robot_options
    from roboscript.demo import DEMO_TASK

    run = sub.add_parser(
        "exec", help="run a program on a task's world and evaluate it", epilog=EXIT_STATUS_HELP
    )
    run.add_argument("program", help="a Python file written against the tool API")
    scene = run.add_mutually_exclusive_group(required=True)
    scene.add_argument("--task", help="a task id (see `roboscript tasks`): its world, and its checks")
    scene.add_argument("--world", help="a world name or file to act in; without a task nothing is checked")
    run.add_argument("--video", default=None, help=VIDEO_HELP)
    run.add_argument("--record", default=None, help=RECORD_HELP)
    add_run_options(run, trials=1)
    add_robot_options(run)
    run.set_defaults(func=cmd_exec)
    ask = sub.add_parser(
        "run",
        help="have an LLM write a program for an instruction, run it and evaluate it",
        epilog=EXIT_STATUS_HELP,
    )
    ask.add_argument("instruction", help="what the robot should do, in words")
    where = ask.add_mutually_exclusive_group(required=True)
    where.add_argument("--task", help="the task whose world (and checks) to use")
    where.add_argument("--world", help="a world name or file to act in; without a task nothing is checked")
    ask.add_argument(
        "--llm",
        default=None,
        help="openai:MODEL[@URL] | llama:PATH.gguf | replay:DIR=NAME | "
        "record:DIR=SPEC | cache:DIR=SPEC; default: $ROBOSCRIPT_LLM or $ROBOSCRIPT_LLM_MODEL",
    )
    ask.add_argument("--show-code", action="store_true", help="print the generated program")
    ask.add_argument(
        "--repair",
        type=rounds,
        default=0,
        help="rounds of feeding checker, runtime and planning errors back to the LLM",
    )
    ask.add_argument("--video", default=None, help=VIDEO_HELP)
    ask.add_argument("--record", default=None, help=RECORD_HELP)
    add_run_options(ask, trials=1)
    add_robot_options(ask)
    ask.set_defaults(func=cmd_run)
    report = sub.add_parser("report", help="runs side by side: markdown, CSV, plots and an HTML page with videos")
    report.add_argument(
        "runs", nargs="+", help="run directories (`roboscript bench`), or folders of them (a sweep's, a study's)"
    )
    report.add_argument("--out", default="out/report", help="where the markdown, CSV, plots and index.html go")
    report.add_argument(
        "--metric",
        default="all",
        choices=["all", *METRICS],
        help="the metric the tables and plots show",
    )
    report.set_defaults(func=cmd_report)
    demo = sub.add_parser(
        "demo",
        help="one task end to end (the configured LLM, else the reference program) with a video and a report",
        epilog="exit status: 0 when the task was done, 1 when it was not, 2 for a usage error or a missing optional "
        "part",
    )
    demo.add_argument("--task", default=DEMO_TASK, help="the task to run (see `roboscript tasks`)")
    demo.add_argument("--robot", choices=ROBOT_NAMES, default="panda", help="the arm")
    demo.add_argument("--llm", default=None, help="an LLM spec (see `run --llm`); default: the environment's")
    demo.add_argument("--repair", type=rounds, default=0, help="repair rounds when an LLM writes the program")
    demo.add_argument("--seed", type=int, default=0, help="the world's randomisation")
    demo.add_argument("--timeout", type=seconds, default=300.0, help="time limit of the program, wall seconds")
    demo.add_argument("--out", default="out/demo", help="where the video and the report go")
    add_perception_option(demo)
    add_suite_option(demo)
    demo.set_defaults(func=cmd_demo)
    bench = sub.add_parser(
        "bench",
        help="run the benchmark (resumes an interrupted run in --out)",
        epilog="exit status: 0 when every trial of every task passed its checks, 1 when one did not, 2 for a usage "
        "error or a missing optional part",
    )
    bench.add_argument(
        "--policy",
        default="reference",
        help="where programs come from: reference; llm:SPEC (see `run --llm`); or programs:PATH, a folder of "
        "<task_id>.py files or files in the original's generated-code format (JSON: query, code_str, src_fs)",
    )
    bench.add_argument(
        "--repair",
        type=rounds,
        default=0,
        help="rounds of feeding checker, runtime and planning errors back (LLM policies); the summary shows both",
    )
    bench.add_argument("--tasks", default=None, help="comma-separated task ids; default: all")
    bench.add_argument(
        "--out", default=None, help="run directory; default out/bench/<policy>_<robot> (an LLM by its model's name)"
    )
    bench.add_argument(
        "--videos",
        choices=VIDEO_CHOICES,
        default="none",
        help="which trials keep a video (camera_left) in <out>/videos: none, failed (the failures, to see why) or all",
    )
    add_run_options(bench, trials=10)
    bench.set_defaults(func=cmd_bench)

