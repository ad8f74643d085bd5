"""The ``roboscript`` command."""

from __future__ import annotations

import argparse
import json
import os
import signal
import sys
import threading
import time
from pathlib import Path

# roboscript.robots.ROBOTS, named here so that --help imports no MuJoCo (a test holds the two equal)
ROBOT_NAMES = ("panda", "ur5e", "fr3")


def cmd_worlds(args: argparse.Namespace) -> int:
    from roboscript.sim.world_catalog import load_world, world_names

    for name in world_names():
        world = load_world(name)
        parts = ", ".join(world.part_names()) if world.cabinets else ""
        print(f"{name}")
        print(f"    {world.description}")
        print(f"    objects: {', '.join(world.object_names())}")
        if parts:
            print(f"    parts:   {parts}")
    return 0


def cmd_objects(args: argparse.Namespace) -> int:
    from roboscript.objects import object_types

    print(f"{'type':26s} {'category':12s} {'colour':12s} {'shape':10s} size (cm)")
    for name, obj in sorted(object_types().items()):
        size = " x ".join(f"{v * 100:.1f}" for v in obj.size)
        notes = [k for k, v in (("container", obj.container), ("not picked", not obj.pickable)) if v]
        extra = f"  ({', '.join(notes)})" if notes else ""
        print(f"{name:26s} {obj.category:12s} {obj.color:12s} {obj.shape:10s} {size}{extra}")
    return 0


def cmd_assets(args: argparse.Namespace) -> int:
    from roboscript.robots.assets import KNOWN_MODELS, AssetNotFoundError, optional_and_absent, resolve_model

    status = 0
    for name in KNOWN_MODELS:
        try:
            found = resolve_model(name)
            print(f"{name:24s} {found.source}: {found.xml_path}")
        except AssetNotFoundError as exc:
            if optional_and_absent(KNOWN_MODELS[name]):
                print(f"{name:24s} not installed (optional: pip install 'roboscript[{KNOWN_MODELS[name].extra}]')")
                continue
            print(f"{name:24s} NOT FOUND\n{exc}", file=sys.stderr)
            status = 1
    return status


def cmd_render(args: argparse.Namespace) -> int:
    from roboscript.backends.mujoco_backend import MujocoBackend
    from roboscript.backends.mujoco_snapshot import write_snapshot

    started = time.perf_counter()
    with MujocoBackend(
        args.world, robot=args.robot, seed=args.seed, randomize=args.randomize, settle=args.settle
    ) as backend:
        written = write_snapshot(backend, Path(args.out))
        print(
            f"wrote {len(written)} images of {backend.sim_world.spec.name} ({backend.robot.name}) to {args.out} "
            f"in {time.perf_counter() - started:.1f} s"
        )
    return 0


def cmd_ros_sim(args: argparse.Namespace) -> int:
    from roboscript.robot_config import load_robot_config, ros_config_for
    from roboscript.sim.world_catalog import load_world

    robot = args.robot or load_world(args.world).robot
    config = load_robot_config(args.robot_config or ros_config_for(robot))
    if config.robot.name != robot:
        raise ValueError(f"robot configuration {config.name} is for the {config.robot.name}, not the {robot}")
    if not os.environ.get("ROS_MASTER_URI"):
        raise ValueError("ROS_MASTER_URI is not set: start a master (rosmaster --core -p 11311) and export its URI")
    try:
        from roboscript.ros.sim_server import serve
    except ImportError as exc:
        raise ValueError(f"ros-sim needs ROS 1 (rospy, actionlib): see the README's ROS section ({exc})") from None
    task = None
    if args.task:
        from roboscript.bench.tasks import get_task

        task = get_task(args.task, args.suite)
    serve(args.world, robot, config, args.real_time_factor, args.camera_rate, args.seed, args.randomize, task=task)
    return 0


def cmd_tasks(args: argparse.Namespace) -> int:
    from roboscript.bench.tasks import load_suite, suite_names

    tasks = load_suite(args.suite)
    if not args.json:
        print(f"suite {args.suite} (suites: {', '.join(suite_names())})\n")
    rows = []
    for task in tasks.values():
        checks = [c.describe() for c in task.checks]
        world = Path(task.world).stem
        rows.append({"id": task.id, "label": task.label, "world": world, "query": task.query, "checks": checks})
        if not args.json:
            label = f" (label {task.label})" if task.label and task.label != task.id else ""
            print(f"{task.id}{label}  world {world}")
            print(f"    {task.query}")
            print(f"    checks: {'; '.join(checks)}")
    if args.json:
        print(json.dumps({"suite": args.suite, "tasks": rows}))
    return 0


def _print_result(result: dict) -> None:
    print(
        f"{result['task']} ({result['robot']}, {result['trials']} trials): "
        f"grammar {result['grammar_correctness']:.2f}, semantic {result['semantic_correctness']:.2f}, "
        f"finished steps {result['finished_steps_ratio']:.2f}, whole task {result['whole_task_success']:.2f}"
    )
    for trial in result["per_trial"]:
        passed = sum(c["passed"] for c in trial["checks"])
        line = f"  trial {trial['trial']} (seed {trial['seed']}): {passed}/{len(trial['checks'])} checks"
        line += f", sim {trial['sim_time_s']:.1f} s, wall {trial['wall_time_s']:.1f} s"
        printed = trial.get("output", "").strip()
        if printed:
            line += "\n    output:" + "".join(f"\n      {text}" for text in printed.splitlines())
        if trial["error"]:
            line += f"\n    error: {trial['error']}"
        for check in trial["checks"]:
            if not check["passed"]:
                line += f"\n    failed: {check['check']}: {check['detail']}"
        print(line)


def cmd_exec(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import progress_printer, trial_specs
    from roboscript.bench.metrics import task_result
    from roboscript.bench.runner import run_isolated
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.cli_robot import robot_requested, run_on_running_robot

    scene = args.world or get_task(args.task, args.suite).world
    path = Path(args.program)
    if not path.is_file():
        raise ValueError(f"no program file {str(path)!r}")
    program = path.read_text()
    if robot_requested(args):
        return run_on_running_robot(args, program, scene)
    label = free_task(args.world, "run the program").id if args.world else args.task
    specs = trial_specs(
        label,
        program,
        args.robot,
        args.trials,
        args.seed,
        args.timeout,
        args.video,
        perception=args.perception,
        suite=args.suite,
        backend=args.backend,
        robot_config=args.robot_config,
        world=args.world,
        instruction="run the program" if args.world else None,
        record=args.record,
    )
    records = run_isolated(specs, args.jobs, None if args.json else progress_printer(len(specs)))
    result = task_result(label, args.robot, records)
    if args.json:
        print(json.dumps(result))
    else:
        _print_result(result)
    return 0


def cmd_bench(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import run_benchmark

    tasks = [t.strip() for t in args.tasks.split(",") if t.strip()] if args.tasks else None
    from roboscript.bench.benchmark import default_out, run_label

    if args.repair and not args.policy.startswith("llm:"):
        raise ValueError("--repair needs an LLM policy (--policy llm:SPEC)")
    out = args.out or default_out(
        run_label(args.policy, args.repair), args.robot, args.perception, args.suite, args.backend
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
    )
    if args.json:
        print(json.dumps({"tasks": result["tasks"], "wall_time_s": result["wall_time_s"]}))
    else:
        print((Path(result["out"]) / "summary.md").read_text())
        print(f"wall time {result['wall_time_s']:.1f} s; results in {result['out']}")
    return 0


def cmd_run(args: argparse.Namespace) -> int:
    from roboscript.bench.benchmark import trial_specs
    from roboscript.bench.metrics import task_result
    from roboscript.bench.runner import run_isolated
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.cli_robot import robot_requested
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
    specs = trial_specs(
        label,
        "",
        args.robot,
        args.trials,
        args.seed,
        args.timeout,
        args.video,
        llm=args.llm or llm.name,
        instruction=args.instruction,
        repair_rounds=args.repair,
        world=args.world,
        perception=args.perception,
        suite=args.suite,
        backend=args.backend,
        robot_config=args.robot_config,
        record=args.record,
    )
    records = run_isolated(specs, args.jobs)
    result = task_result(label, args.robot, records)
    if args.json:
        print(json.dumps({**result, "programs": [r.program for r in records]}))
        return 0
    for record in records:
        for i, attempt in enumerate(record.attempts[:-1]):
            print(f"trial {record.trial}, attempt {i + 1}: {attempt['outcome']}: {attempt['error']} (repaired)")
        print(f"trial {record.trial}: {record.outcome}" + (f": {record.error}" if record.error else ""))
        if args.show_code and record.program is not None:
            print(record.program)
    if args.world:
        print(f"world {args.world} has no task, so nothing was checked; outcome: {records[0].outcome}")
        return 0 if all(r.ok for r in records) else 1
    _print_result(result)
    return 0


def _run_llm_on_robot(args: argparse.Namespace, llm, label: str) -> int:
    """``run --master``: the LLM writes the program once, for the scene's names; it then runs as ``exec`` would."""
    from roboscript.bench.tasks import free_task, get_task
    from roboscript.cli_robot import run_on_running_robot
    from roboscript.codegen.agent import CodeAgent

    task = free_task(args.world, args.instruction) if args.world else get_task(args.task, args.suite)
    program = CodeAgent(llm).write_program(task.query_for(args.instruction)).program
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
    print(f"simulated {record.sim_time_s:.1f} s in {record.wall_time_s:.1f} s wall")
    print(f"report: {plan.out / 'report.md'}; video: {plan.out / (task.id + '.mp4')}")
    return 0 if record.success else 1


def cmd_report(args: argparse.Namespace) -> int:
    from roboscript.report.write import write_report

    report = write_report(args.runs, args.out, args.metric)
    print(report.markdown)
    for note in report.notes:
        print(note, file=sys.stderr)
    print(f"report of {len(report.runs)} runs: {', '.join(str(p) for p in report.files)}")
    return 0


def _rounds(text: str) -> int:
    """``--repair``: a whole number of rounds, 0 or more."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number of rounds, got {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"repair rounds must be 0 or more, got {value}")
    return value


def _add_run_options(parser: argparse.ArgumentParser) -> None:
    from roboscript.bench.runner import default_jobs

    parser.add_argument("--robot", choices=ROBOT_NAMES, default="panda")
    parser.add_argument("--trials", type=int, default=10)
    parser.add_argument("--seed", type=int, default=0, help="trial i uses seed + i for the world's randomisation")
    parser.add_argument("--timeout", type=float, default=300.0, help="time limit of one program, wall seconds")
    parser.add_argument("--jobs", type=int, default=default_jobs(), help="trials run at once (one process each)")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    _add_perception_option(parser)
    _add_suite_option(parser)


def _add_suite_option(parser: argparse.ArgumentParser) -> None:
    from roboscript.bench.tasks import DEFAULT_SUITE, suite_names

    parser.add_argument(
        "--suite",
        type=_suite,
        default=DEFAULT_SUITE,
        help=f"the tasks' suite: {', '.join(suite_names())} (default {DEFAULT_SUITE}), or a suite file's path",
    )


def _suite(text: str) -> str:
    """``--suite``: a packaged suite's name, or a suite file's path (made absolute for the trial processes)."""
    from roboscript.bench.tasks import load_suite, suite_path
    from roboscript.datafile import names_a_file

    try:
        path = suite_path(text)
        load_suite(text)
    except (KeyError, ValueError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        raise argparse.ArgumentTypeError(message) from None
    return str(path) if names_a_file(text) else text


def _add_perception_option(parser: argparse.ArgumentParser) -> None:
    from roboscript.perception.modes import PERCEPTION_MODES

    modes = "; ".join(f"{m}: {what}" for m, what in PERCEPTION_MODES.items())
    modes += "; gt-2d, gt-3d and gt-scene combine with '+' (gt-2d+gt-scene)"
    parser.add_argument(
        "--perception",
        type=_perception_mode,
        default=None,
        metavar="MODE",
        help=modes + "; default: gt, or full with --backend ros or franky",
    )
    parser.add_argument(
        "--backend",
        choices=["mujoco", "ros", "franky"],
        default="mujoco",
        help="mujoco: the simulation in-process; ros: the world served by `roboscript ros-sim` on a master of the "
        "trial's own, the tools on the ROS backend, perception from the cameras and the segmentation topic; franky: "
        "the world served by franky-sim, its FR3 (--robot fr3) driven through libfranka, perception from the cameras",
    )
    parser.add_argument(
        "--robot-config",
        default=None,
        help="with --backend ros: a robot configuration file or packaged name (default: the arm's packaged one)",
    )
    parser.add_argument(
        "--detector",
        default=None,
        metavar="KIND[:PATH]",
        help="the detector of modes without ground-truth 2D boxes: trained (the packaged model this project trains), "
        "trained:FILE.npz (from train-detector), owlv2:DIR or grounding-dino:DIR (DIR written by save_pretrained); "
        "default: $ROBOSCRIPT_DETECTOR, else trained",
    )


def _perception_mode(text: str):
    from roboscript.perception.modes import parse_mode

    try:
        return parse_mode(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _resolve_perception(args: argparse.Namespace) -> None:
    """The perception mode with its detector, from --detector or the environment: the one place either is read.
    A missing detector fails here, before any world is built."""
    from roboscript.perception.modes import DETECTOR_ENV, SEGMENTATION, perception_mode

    backend = getattr(args, "backend", "mujoco")
    on_robot = backend == "ros"
    mode = args.perception or ("full" if backend in ("ros", "franky") else "gt")
    # A robot served by ros-sim (or with a segmentation node) grounds phrases in its segmentation topic by default.
    detector = args.detector or os.environ.get(DETECTOR_ENV) or (SEGMENTATION if on_robot else None)
    args.perception = perception_mode(mode, detector)


RECORD_HELP = (
    "record the trial into this MCAP file for Foxglove: camera images, perceived boxes, planning scene, planned "
    "and executed paths, and every tool call with its answer (needs roboscript[record])"
)


def build_parser() -> argparse.ArgumentParser:
    from roboscript.bench.metrics import METRICS
    from roboscript.cli_detector import add_detector_commands
    from roboscript.cli_generate import add_generate_commands
    from roboscript.cli_robot import add_replay_command, add_robot_options
    from roboscript.cli_studies import add_study_commands
    from roboscript.demo import DEMO_TASK

    parser = argparse.ArgumentParser(prog="roboscript", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("worlds", help="list the packaged worlds").set_defaults(func=cmd_worlds)
    sub.add_parser("objects", help="list the object library").set_defaults(func=cmd_objects)
    sub.add_parser("assets", help="show where each robot model is found").set_defaults(func=cmd_assets)
    render = sub.add_parser("render", help="render every camera of a world to PNG files")
    render.add_argument("world", help="a world name (see `roboscript worlds`) or a world file path")
    render.add_argument("--robot", choices=ROBOT_NAMES, default=None, help="default: the world's robot")
    render.add_argument("--out", required=True, help="output directory")
    render.add_argument("--seed", type=int, default=0)
    render.add_argument("--randomize", action="store_true", help="jitter object poses (deterministic per seed)")
    render.add_argument("--settle", type=float, default=1.0, help="simulated seconds to settle first")
    render.set_defaults(func=cmd_render)
    ros_sim = sub.add_parser("ros-sim", help="serve a simulated world as a ROS robot (the digital twin)")
    ros_sim.add_argument("world", help="a world name (see `roboscript worlds`) or a world file path")
    ros_sim.add_argument("--robot", choices=["panda", "ur5e"], default=None, help="default: the world's robot")
    ros_sim.add_argument(
        "--robot-config",
        default=None,
        help="the names to serve under: a robot configuration file or packaged name; default: panda_franka_ros "
        "or ur5e_ur_robot_driver",
    )
    ros_sim.add_argument(
        "--real-time-factor", type=float, default=1.0, help="simulated seconds per wall-clock second (default 1)"
    )
    ros_sim.add_argument("--camera-rate", type=float, default=1.0, help="camera images per simulated second")
    ros_sim.add_argument("--seed", type=int, default=0)
    ros_sim.add_argument("--randomize", action="store_true", help="jitter object poses (deterministic per seed)")
    ros_sim.add_argument(
        "--task", default=None, help="a task whose checks the twin evaluates when asked on /roboscript/evaluate"
    )
    ros_sim.add_argument("--suite", default="paper", help="the task's suite (default: paper)")
    ros_sim.set_defaults(func=cmd_ros_sim)
    tasks = sub.add_parser("tasks", help="list a suite's tasks: worlds, queries and checks")
    tasks.add_argument("--json", action="store_true", help="print one JSON object")
    _add_suite_option(tasks)
    tasks.set_defaults(func=cmd_tasks)
    run = sub.add_parser("exec", help="run a program on a task's world and evaluate it")
    run.add_argument("program", help="a Python file written against the tool API")
    scene = run.add_mutually_exclusive_group(required=True)
    scene.add_argument("--task", help="a task id (see `roboscript tasks`): its world, and its checks")
    scene.add_argument("--world", help="a world name or file to act in; without a task nothing is checked")
    run.add_argument("--video", default=None, help="record camera_left into this MP4 file")
    run.add_argument("--record", default=None, help=RECORD_HELP)
    _add_run_options(run)
    add_robot_options(run)
    run.set_defaults(func=cmd_exec)
    ask = sub.add_parser("run", help="have an LLM write a program for an instruction, run it and evaluate it")
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
        type=_rounds,
        default=0,
        help="rounds of feeding checker, runtime and planning errors back to the LLM",
    )
    ask.add_argument("--video", default=None, help="record camera_left into this MP4 file")
    ask.add_argument("--record", default=None, help=RECORD_HELP)
    _add_run_options(ask)
    add_robot_options(ask)
    ask.set_defaults(func=cmd_run, trials=1)
    add_replay_command(sub)
    report = sub.add_parser("report", help="runs side by side: markdown, CSV, plots and an HTML page with videos")
    report.add_argument(
        "runs", nargs="+", help="run directories (`roboscript bench`), or folders of them (a sweep's, a study's)"
    )
    report.add_argument("--out", default="out/report", help="where the markdown, CSV, plots and index.html go")
    report.add_argument(
        "--metric",
        default="all",
        choices=["all", *METRICS],
    )
    report.set_defaults(func=cmd_report)
    add_study_commands(sub)
    add_generate_commands(sub, ROBOT_NAMES)
    add_detector_commands(sub)
    demo = sub.add_parser(
        "demo", help="one task end to end (the configured LLM, else the reference program) with a video and a report"
    )
    demo.add_argument("--task", default=DEMO_TASK, help="the task to run (see `roboscript tasks`)")
    demo.add_argument("--robot", choices=ROBOT_NAMES, default="panda")
    demo.add_argument("--llm", default=None, help="an LLM spec (see `run --llm`); default: the environment's")
    demo.add_argument("--repair", type=_rounds, default=0, help="repair rounds when an LLM writes the program")
    demo.add_argument("--seed", type=int, default=0)
    demo.add_argument("--timeout", type=float, default=300.0, help="time limit of the program, wall seconds")
    demo.add_argument("--out", default="out/demo", help="where the video and the report go")
    _add_perception_option(demo)
    _add_suite_option(demo)
    demo.set_defaults(func=cmd_demo)
    bench = sub.add_parser("bench", help="run the benchmark (resumes an interrupted run in --out)")
    bench.add_argument(
        "--policy",
        default="reference",
        help="where programs come from: reference; llm:SPEC (see `run --llm`); or programs:PATH, a folder of "
        "<task_id>.py files or files in the original's generated-code format (JSON: query, code_str, src_fs)",
    )
    bench.add_argument(
        "--repair",
        type=_rounds,
        default=0,
        help="rounds of feeding checker, runtime and planning errors back (LLM policies); the summary shows both",
    )
    bench.add_argument("--tasks", default=None, help="comma-separated task ids; default: all")
    bench.add_argument("--out", default=None, help="run directory; default out/bench/<policy>_<robot>")
    _add_run_options(bench)
    bench.set_defaults(func=cmd_bench)
    return parser


def _exit_on_sigterm(signum, frame) -> None:
    # SystemExit unwinds like Ctrl-C does, so running trials are stopped and results written so far are kept.
    sys.exit(128 + signum)


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    if (
        args.command in ("exec", "run", "bench", "sweep", "study", "generate")
        and threading.current_thread() is threading.main_thread()
    ):
        signal.signal(signal.SIGTERM, _exit_on_sigterm)
    from roboscript.errors import RoboScriptError, error_message

    try:
        if hasattr(args, "perception"):
            _resolve_perception(args)
        return args.func(args)
    except (RoboScriptError, KeyError, ValueError) as exc:  # the builtins: argument checks in the commands
        print(f"roboscript: error: {error_message(exc)}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
