"""What the package holds, listed and drawn: ``worlds``, ``objects``, ``assets``, ``render``, ``tasks``."""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

from roboscript import extras
from roboscript.cli.options import (
    ROBOT_NAMES,
    add_suite_option,
)


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
                print(f"{name:24s} not installed (optional: {extras.install_hint(KNOWN_MODELS[name].extra)})")
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


def cmd_tools(args: argparse.Namespace) -> int:
    from roboscript.codegen.prompt import tool_reference

    print(tool_reference())
    return 0


def add_catalog_commands(sub) -> None:
    sub.add_parser("tools", help="the tool API as the LLM sees it: every tool with its doc-string").set_defaults(
        func=cmd_tools
    )
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
    tasks = sub.add_parser("tasks", help="list a suite's tasks: worlds, queries and checks")
    tasks.add_argument("--json", action="store_true", help="print one JSON object")
    add_suite_option(tasks)
    tasks.set_defaults(func=cmd_tasks)

