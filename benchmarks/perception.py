"""Perception benchmark: how well the chain sees each packaged world, and how long one look takes.

Run: python benchmarks/perception.py [--repeats 5] [--robot panda] [--voxel 0.005] [--jitter 0] [--dropout 0]

Per world, with 2D boxes from the simulator's segmentation (optionally perturbed): median 3D box IoU and median
centre error of every object found against its ground-truth box, the objects and furniture parts found (a look
asks for both, as ``detect_objects`` does, the furniture and parts for their geometry), and the share of
cross-view tuples whose boxes all show one object or part. Timing, median over ``--repeats``: rendering the
cameras, TSDF fusion, and the rest (grounding, projection, matching, instances); "look" is their sum, what
``detect_objects`` costs.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.evaluation import score_instances, tuple_is_correct
from roboscript.perception.fusion import FusionSettings
from roboscript.perception.grounding import GroundingNoise, SegmentationGrounder, normalize_phrase
from roboscript.perception.observation import observe
from roboscript.perception.pipeline import shows_in_pieces
from roboscript.sim.world_catalog import world_names


def measure(world: str, robot: str, repeats: int, settings: FusionSettings, noise: GroundingNoise) -> dict:
    backend = MujocoBackend(world, robot=robot)
    try:
        gt = backend.ground_truth
        objects = [e.name for e in gt.world.entities if e.kind == "object"]
        # Furniture and its parts are looked for too, as detect_objects does: their geometry is measured from them.
        parts = [e.name for e in gt.world.entities if e.kind in ("furniture", "part")]
        pieces = {normalize_phrase(p) for p in parts if shows_in_pieces(p)}
        robot_index = gt.world.entity("robot").index
        grounder = SegmentationGrounder(gt.world.entities, noise=noise)
        render, fusion, rest = [], [], []
        for _ in range(repeats):
            t0 = time.perf_counter()
            frames = [backend.capture(c) for c in backend.camera_names()]
            t1 = time.perf_counter()
            masks = [f.segmentation == robot_index for f in frames]
            seen = observe(frames, grounder, objects + parts, settings, masks, pieces=pieces)
            t2 = time.perf_counter()
            render.append(t1 - t0)
            fusion.append(seen.scene.seconds)
            rest.append(t2 - t1 - seen.scene.seconds)
        labels = {normalize_phrase(o) for o in objects}
        scores = score_instances([i for i in seen.instances if i.label in labels], seen.detections, gt)
        correct = [tuple_is_correct(m, seen.detections) for m in seen.matched]
        return {
            "world": world,
            "objects": len(objects),
            "found": len({s.name for s in scores}),
            "parts": len(parts),
            "parts_found": len({i.label for i in seen.instances} - labels),
            "iou": float(np.median([s.iou for s in scores])) if scores else 0.0,
            "center_cm": float(np.median([s.center_error for s in scores]) * 100) if scores else float("nan"),
            "tuples_correct": float(np.mean(correct)) if correct else 0.0,
            "cameras": len(frames),
            "render_s": statistics.median(render),
            "fusion_s": statistics.median(fusion),
            "rest_s": statistics.median(rest),
            "look_s": statistics.median([a + b + c for a, b, c in zip(render, fusion, rest, strict=True)]),
        }
    finally:
        backend.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--robot", choices=["panda", "ur5e"], default="panda")
    parser.add_argument("--voxel", type=float, default=0.005)
    parser.add_argument("--jitter", type=float, default=0.0, help="box edges moved by up to this fraction")
    parser.add_argument("--dropout", type=float, default=0.0, help="chance a 2D box is missed")
    args = parser.parse_args()
    settings = FusionSettings(voxel=args.voxel, truncation=4 * args.voxel)
    noise = GroundingNoise(box_jitter=args.jitter, dropout=args.dropout)
    header = (
        f"{'world':32s} {'found':>7s} {'parts':>7s} {'IoU':>5s} {'ctr cm':>6s} {'tuples':>6s} {'cams':>4s} "
        f"{'render':>7s} {'fusion':>7s} {'rest':>6s} {'look':>6s}"
    )
    print(header, flush=True)
    rows = []
    for world in world_names():
        r = measure(world, args.robot, args.repeats, settings, noise)
        rows.append(r)
        print(
            f"{r['world']:32s} {r['found']:>3d}/{r['objects']:<3d} {r['parts_found']:>3d}/{r['parts']:<3d} "
            f"{r['iou']:5.2f} {r['center_cm']:6.2f} "
            f"{r['tuples_correct']:6.0%} {r['cameras']:>4d} {r['render_s']:7.3f} {r['fusion_s']:7.3f} "
            f"{r['rest_s']:6.3f} {r['look_s']:6.3f}",
            flush=True,
        )
    looks = [r["look_s"] for r in rows]
    print(
        f"median over worlds: IoU {statistics.median(r['iou'] for r in rows):.2f}, centre error "
        f"{statistics.median(r['center_cm'] for r in rows):.2f} cm, one look {statistics.median(looks):.3f} s "
        f"(max {max(looks):.3f} s)"
    )


if __name__ == "__main__":
    main()
