"""``roboscript generate``: random worlds, scene descriptions, LLM-suggested tasks, template task suites and
verified data sets."""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path


def cmd_worlds(args: argparse.Namespace) -> int:
    from roboscript.generate.preview import settle
    from roboscript.generate.recipe import load_recipe
    from roboscript.generate.worlds import generate_worlds

    recipe = load_recipe(args.recipe)
    unsettled = []

    def report(world, path: Path) -> None:
        if not args.images:
            print(f"{path}")
            return
        settled = settle(world.spec, path.with_suffix(".png"))
        name, moved = settled.worst()
        state = "settled" if settled.ok else "DID NOT SETTLE"
        print(f"{path}: {len(world.spec.objects)} objects, {state} (most moved: {name}, {moved * 100:.1f} cm)")
        if not settled.ok:
            unsettled.append(path.name)

    started = time.perf_counter()
    paths = generate_worlds(recipe, args.count, args.seed, args.out, args.prefix, report)
    print(f"{len(paths)} worlds in {args.out} ({time.perf_counter() - started:.1f} s)", file=sys.stderr)
    if unsettled:
        print(f"did not settle: {', '.join(unsettled)}", file=sys.stderr)
        return 1
    return 0


def cmd_describe(args: argparse.Namespace) -> int:
    from roboscript.generate.describe import describe_world

    print(describe_world(args.world, args.seed, args.randomize))
    return 0


def cmd_tasks(args: argparse.Namespace) -> int:
    import yaml

    from roboscript.backends.mujoco_backend import MujocoBackend
    from roboscript.datafile import names_a_file
    from roboscript.generate.describe import describe_scene
    from roboscript.generate.suggest import suggest_tasks
    from roboscript.llm import make_llm
    from roboscript.sim.world_catalog import load_world

    llm = make_llm(args.llm)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    kept, rejected = [], []
    for world_arg in args.worlds:
        world = load_world(world_arg)
        is_file = names_a_file(world_arg)
        ref = os.path.relpath(Path(world_arg).resolve(), out.parent.resolve()) if is_file else world_arg
        with MujocoBackend(world) as backend:
            description = describe_scene(world, backend.ground_truth)
            result = suggest_tasks(llm, world, ref, out.parent.resolve(), description, backend.ground_truth, args.count)
        for entry in result.kept:
            entry["id"] = f"{world.name}.{len(kept)}"
            kept.append(entry)
            print(f"kept     {world.name}: {entry['query'].split('# ', 1)[1]}")
        for r in result.rejected:
            rejected.append({"world": ref, "index": r.index, "suggestion": r.suggestion, "reason": r.reason})
            print(f"rejected {world.name}[{r.index}]: {r.reason}")
    log = out.with_suffix(".rejected.jsonl")
    log.write_text("".join(json.dumps(r, ensure_ascii=False) + "\n" for r in rejected))
    if not kept:
        print(f"no suggestion held; reasons in {log}", file=sys.stderr)
        return 1
    suite = {"suite": out.stem, "description": f"Tasks suggested by {llm.name}.", "tasks": kept}
    out.write_text(yaml.safe_dump(suite, sort_keys=False, width=200))
    print(f"{len(kept)} tasks kept in {out}, {len(rejected)} rejected ({log})")
    return 0


def cmd_benchmark(args: argparse.Namespace) -> int:
    from collections import Counter

    from roboscript.generate.recipe import load_recipe
    from roboscript.generate.suite import generate_tasks, write_suite

    recipe = load_recipe(args.recipe)
    more = _more_worlds(args.more)
    tasks = generate_tasks(recipe, args.worlds, args.seed, args.families, args.per_world, more=more)
    worlds = f"{args.worlds} worlds generated from recipe {recipe.name!r}" + "".join(
        f" and {count} from {r.name!r}" for r, count in more
    )
    command = f"roboscript generate benchmark --worlds {args.worlds} --seed {args.seed}" + "".join(
        f" --more {spec}" for spec in args.more
    )
    description = (
        f"Template tasks of {len({t.task.family for t in tasks})} families over {worlds} with seed {args.seed}, "
        f"the oracle programs as reference (`{command}`)."
    )
    path = write_suite(tasks, args.out, args.name, description)
    counts = Counter(t.task.family for t in tasks)
    made = len({t.world.name for t in tasks})
    print(f"{len(tasks)} tasks over {made} worlds in {path}: " + ", ".join(f"{f} {n}" for f, n in counts.items()))
    return 0


def cmd_dataset(args: argparse.Namespace) -> int:
    from collections import Counter

    from roboscript.bench.runner import default_jobs
    from roboscript.generate.dataset import generate_dataset
    from roboscript.generate.recipe import load_recipe

    outcome = generate_dataset(
        load_recipe(args.recipe),
        args.worlds,
        args.seed,
        args.out,
        args.policy,
        args.robot,
        args.jobs or default_jobs(),
        args.families,
        args.per_world,
        args.timeout,
    )
    counts = Counter(r.family for r in outcome.records)
    print(
        f"{len(outcome.records)} of {outcome.trials} programs passed their checks and were kept in {outcome.path} "
        f"({outcome.wall_time_s:.0f} s): " + ", ".join(f"{f} {n}" for f, n in sorted(counts.items()))
    )
    return 0


def _families(text: str) -> list[str]:
    from roboscript.generate.families import FAMILIES

    names = [n.strip() for n in text.split(",") if n.strip()]
    for name in names:
        if name not in FAMILIES:
            raise argparse.ArgumentTypeError(f"unknown family {name!r}; families: {', '.join(FAMILIES)}")
    return names


def _more_worlds(specs: list[str]) -> list:
    """``RECIPE:N`` entries of ``--more`` as ``(recipe, N)``."""
    from roboscript.generate.recipe import load_recipe

    out = []
    for spec in specs:
        name, _, count = spec.rpartition(":")
        if not name or not count.isdigit() or int(count) < 1:
            raise SystemExit(f"--more takes RECIPE:N with N a whole number from 1 (e.g. cupboard:20), got {spec!r}")
        out.append((load_recipe(name), int(count)))
    return out


def _task_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--worlds", type=int, required=True, help="how many worlds to generate")
    parser.add_argument("--seed", type=int, default=0, help="world i of seed S is the same in every run")
    parser.add_argument("--recipe", default="tabletop", help="a packaged recipe (tabletop) or a recipe file")
    parser.add_argument("--families", type=_families, default=None, help="comma-separated families (default: all)")
    parser.add_argument("--per-world", type=int, default=4, help="tasks of distinct families per world, at most")
    parser.add_argument(
        "--more", action="append", default=[], metavar="RECIPE:N", help="N further worlds of RECIPE (repeatable)"
    )


def add_generate_commands(sub, robot_names: tuple[str, ...]) -> None:
    """``generate worlds|describe|tasks|benchmark|dataset`` on the ``roboscript`` parser's subcommands."""
    generate = sub.add_parser("generate", help="random worlds, scene descriptions, suggested and template tasks, data")
    what = generate.add_subparsers(dest="what", required=True)

    worlds = what.add_parser("worlds", help="random valid tabletop worlds, each with its view from above")
    worlds.add_argument("count", type=int, help="how many worlds")
    worlds.add_argument("--seed", type=int, default=0, help="world i of seed S is the same in every run")
    worlds.add_argument("--recipe", default="tabletop", help="a packaged recipe (tabletop) or a recipe file")
    worlds.add_argument("--out", default="out/worlds", help="where the world files (and images) go")
    worlds.add_argument("--prefix", default=None, help="world names' prefix (default gen_<seed>)")
    worlds.add_argument(
        "--no-images", dest="images", action="store_false", help="skip building each world (settling, top view)"
    )
    worlds.set_defaults(func=cmd_worlds)

    describe = what.add_parser("describe", help="a world's scene in words, after it settles")
    describe.add_argument("world", help="a world name or file")
    describe.add_argument("--seed", type=int, default=0)
    describe.add_argument("--randomize", action="store_true", help="jitter object poses (deterministic per seed)")
    describe.set_defaults(func=cmd_describe)

    tasks = what.add_parser("tasks", help="tasks an LLM suggests for worlds, validated; a suite file of those kept")
    tasks.add_argument("worlds", nargs="+", help="world names or files")
    tasks.add_argument("--llm", default=None, help="an LLM spec (see `run --llm`); default: the environment's")
    tasks.add_argument("--count", type=int, default=5, help="tasks to ask for per world")
    tasks.add_argument("--out", default="out/suggested.yaml", help="the suite file of the tasks kept")
    tasks.set_defaults(func=cmd_tasks)

    bench = what.add_parser("benchmark", help="template tasks with oracle programs over generated worlds, as a suite")
    _task_options(bench)
    bench.add_argument("--name", default="generated", help="the suite's name (its file is <out>/<name>.yaml)")
    bench.add_argument("--out", default="out/suites", help="folder of the suite file")
    bench.set_defaults(func=cmd_benchmark)

    dataset = what.add_parser("dataset", help="(query, world, program) records whose programs passed in simulation")
    _task_options(dataset)
    dataset.add_argument("--policy", default="reference", help="reference (the oracles) or llm:SPEC")
    dataset.add_argument("--robot", choices=robot_names, default="panda")
    dataset.add_argument("--jobs", type=int, default=None, help="trials at once (default: this machine's CPUs)")
    dataset.add_argument("--timeout", type=float, default=300.0, help="time limit of one program, wall seconds")
    dataset.add_argument("--out", default="out/dataset", help="where dataset.jsonl, worlds/ and the run go")
    dataset.set_defaults(func=cmd_dataset)
