"""The ``roboscript`` command."""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np


def _palette(n: int) -> np.ndarray:
    """Distinct colours for segmentation images; index -1 (background) maps to black."""
    rng = np.random.default_rng(7)
    colors = rng.integers(60, 256, size=(max(n, 1), 3), dtype=np.uint8)
    return np.vstack([colors, np.zeros((1, 3), dtype=np.uint8)])


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
    from roboscript.sim.objects import object_types

    print(f"{'type':26s} {'category':12s} {'colour':12s} size (cm)")
    for name, obj in sorted(object_types().items()):
        size = " x ".join(f"{v * 100:.1f}" for v in obj.size)
        print(f"{name:26s} {obj.category:12s} {obj.color:12s} {size}{'  (container)' if obj.container else ''}")
    return 0


def cmd_assets(args: argparse.Namespace) -> int:
    from roboscript.robots.assets import KNOWN_MODELS, AssetNotFoundError, resolve_model

    status = 0
    for name in KNOWN_MODELS:
        try:
            found = resolve_model(name)
            print(f"{name:24s} {found.source}: {found.xml_path}")
        except AssetNotFoundError as exc:
            print(f"{name:24s} NOT FOUND\n{exc}", file=sys.stderr)
            status = 1
    return status


def cmd_render(args: argparse.Namespace) -> int:
    import mujoco
    from PIL import Image

    from roboscript.backends.mujoco_backend import MujocoBackend

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    backend = MujocoBackend(args.world, robot=args.robot, seed=args.seed, randomize=args.randomize, settle=args.settle)
    world = backend.sim_world
    palette = _palette(len(world.entities))
    meta = {
        "world": world.spec.name,
        "robot": backend.robot.name,
        "cameras": {},
        "segmentation_ids": {e.index: e.name for e in world.entities},
    }
    for camera in backend.camera_names():
        frame = backend.capture(camera)
        Image.fromarray(frame.rgb).save(out / f"{camera}_rgb.png")
        depth_mm = np.clip(frame.depth * 1000.0, 0, 65535).astype(np.uint16)
        Image.fromarray(depth_mm).save(out / f"{camera}_depth.png")
        Image.fromarray(palette[frame.segmentation]).save(out / f"{camera}_seg.png")
        np.save(out / f"{camera}_seg.npy", frame.segmentation)
        meta["cameras"][camera] = {
            "width": int(frame.rgb.shape[1]),
            "height": int(frame.rgb.shape[0]),
            "intrinsics": frame.intrinsics.tolist(),
            "camera_to_world": frame.extrinsics.matrix().tolist(),
            "convention": "OpenCV (x right, y down, z forward); depth PNG in millimetres",
        }
    renderer = backend.renderer(1280, 960)
    top = mujoco.MjvCamera()
    top.lookat[:] = [0.0, 0.0, world.spec.table.height]
    top.distance, top.azimuth, top.elevation = 2.6, 180.0, -89.9
    Image.fromarray(renderer.rgb(world.data, top)).save(out / "top_view.png")
    Image.fromarray(renderer.rgb(world.data, "overview")).save(out / "overview.png")
    (out / "cameras.json").write_text(json.dumps(meta, indent=2))
    backend.close()
    print(
        f"wrote {len(backend.camera_names()) * 3 + 2} images of {world.spec.name} ({backend.robot.name}) to {out} "
        f"in {time.perf_counter() - started:.1f} s"
    )
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="roboscript", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    sub.add_parser("worlds", help="list the packaged worlds").set_defaults(func=cmd_worlds)
    sub.add_parser("objects", help="list the object library").set_defaults(func=cmd_objects)
    sub.add_parser("assets", help="show where each robot model is found").set_defaults(func=cmd_assets)
    render = sub.add_parser("render", help="render every camera of a world to PNG files")
    render.add_argument("world", help="a world name (see `roboscript worlds`) or a world file path")
    render.add_argument("--robot", choices=["panda", "ur5e"], default=None, help="default: the world's robot")
    render.add_argument("--out", required=True, help="output directory")
    render.add_argument("--seed", type=int, default=0)
    render.add_argument("--randomize", action="store_true", help="jitter object poses (deterministic per seed)")
    render.add_argument("--settle", type=float, default=1.0, help="simulated seconds to settle first")
    render.set_defaults(func=cmd_render)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    from roboscript.robots.assets import AssetNotFoundError
    from roboscript.sim.world_file import WorldFileError

    try:
        return args.func(args)
    except (WorldFileError, AssetNotFoundError, KeyError, ValueError) as exc:
        message = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
        print(f"roboscript: error: {message}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
