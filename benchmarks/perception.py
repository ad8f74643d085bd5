"""Perception benchmark: how well the chain sees each world, and how long one look takes.

Run: python benchmarks/perception.py [--worlds packaged|generated[:N]|W1,W2] [--detector gt|trained[:FILE]]
                                     [--repeats 5] [--robot panda] [--voxel 0.005] [--jitter 0] [--dropout 0]

Per world, a look asks for every object and for the furniture and its parts (as ``detect_objects`` does). With
``--detector gt`` (the default) the 2D boxes come from the simulator's segmentation (optionally perturbed) and the
robot's pixels from it too: the ``gt-2d`` figures. With ``--detector trained`` they come from the detector this
project trains (the packaged model, or FILE) and the robot's pixels from its model and joint readings (the
self-filter): nothing is read from the simulator but the images, as ``--perception full`` runs; the 2D detections
are then also scored per object and view against the segmentation's boxes (precision and recall at IoU 0.5).

Printed per world: objects found, median 3D box IoU and median centre error of every object found against its
ground-truth box, furniture parts found, the share of cross-view tuples whose boxes all show one object (ground
truth's boxes only), and the median time of one look: rendering the cameras, the robot's pixels, TSDF fusion, and
the rest (grounding, projection, matching, instances).

``--worlds generated:N`` takes the first N worlds of the packaged generated benchmark (``suites/generated``), none of
which the detector was trained on (training renders worlds of another recipe and seed).
"""

from __future__ import annotations

import argparse
import dataclasses
import statistics
import time
from collections.abc import Callable
from importlib import resources
from pathlib import Path

import numpy as np

from roboscript.assembly import fusion_settings
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.detector_training.evaluation import Tally
from roboscript.perception.detection.detector_model import load_detector_model
from roboscript.perception.detection.grounding import GroundingNoise, SegmentationGrounder, normalize_phrase
from roboscript.perception.detection.trained_detector import TrainedDetector
from roboscript.perception.evaluation import box_iou, score_instances, tuple_is_correct
from roboscript.perception.furniture.seen_furniture import shows_in_pieces
from roboscript.perception.reconstruction.fusion import FusionSettings
from roboscript.perception.reconstruction.observation import observe
from roboscript.perception.reconstruction.self_filter import SelfFilter
from roboscript.sim.world_catalog import load_world, world_names


def generated_worlds(count: int | None) -> list[str]:
    folder = Path(str(resources.files("roboscript") / "suites" / "generated" / "worlds"))
    paths = sorted(str(p) for p in folder.glob("*.yaml"))
    return paths[:count] if count else paths


def resolve_worlds(text: str) -> list[str]:
    if text == "packaged":
        return world_names()
    if text.startswith("generated"):
        _, _, count = text.partition(":")
        return generated_worlds(int(count) if count else None)
    return text.split(",")


def measure(world: str, args: argparse.Namespace, settings: FusionSettings, noise: GroundingNoise) -> dict:
    spec = load_world(world)
    backend = MujocoBackend(spec, robot=args.robot)
    try:
        # Fused down to where the product fuses on this backend (not the floor under the table).
        settings = dataclasses.replace(settings, lowest=fusion_settings(backend).lowest)
        gt = backend.ground_truth
        objects = [e.name for e in gt.world.entities if e.kind == "object"]
        parts = [e.name for e in gt.world.entities if e.kind in ("furniture", "part")]
        pieces = {normalize_phrase(p) for p in parts if shows_in_pieces(p)}
        truth_grounder = SegmentationGrounder(gt.world.entities, noise=noise)
        robot_index = gt.world.entity("robot").index
        trained = args.detector != "gt"
        if trained:
            _, _, path = args.detector.partition(":")
            grounder = TrainedDetector.for_scene(spec, load_detector_model(path or None))
            self_filter = SelfFilter(backend.robot, backend.base_pose())
            masks_of: Callable = lambda frames: self_filter.masks(frames, backend.joint_states())  # noqa: E731
        else:
            grounder = truth_grounder
            masks_of = lambda frames: [f.segmentation == robot_index for f in frames]  # noqa: E731
        render, mask, fusion, rest = [], [], [], []
        for _ in range(args.repeats):
            t0 = time.perf_counter()
            frames = [backend.capture(c) for c in backend.camera_names()]
            t1 = time.perf_counter()
            masks = masks_of(frames)
            t2 = time.perf_counter()
            seen = observe(frames, grounder, objects + parts, settings, masks, pieces=pieces)
            t3 = time.perf_counter()
            render.append(t1 - t0)
            mask.append(t2 - t1)
            fusion.append(seen.scene.seconds)
            rest.append(t3 - t2 - seen.scene.seconds)
        labels = {normalize_phrase(o): o for o in objects}
        found_objects = [i for i in seen.instances if i.label in labels]
        if trained:
            scores = [(labels[i.label], i.box) for i in found_objects]
            ious = [box_iou(box, gt.box(name)) for name, box in scores]
            errors = [float(np.linalg.norm(box.center - gt.box(name).center)) for name, box in scores]
            found = {name for name, _ in scores}
            correct = []
        else:
            scored = score_instances(found_objects, seen.detections, gt)
            ious, errors = [s.iou for s in scored], [s.center_error for s in scored]
            found = {s.name for s in scored}
            correct = [tuple_is_correct(m, seen.detections) for m in seen.matched]
        objects_2d, parts_2d = Tally(), Tally()
        if trained:
            for frame, detections in zip(seen.frames, seen.detections, strict=True):
                truth = truth_grounder.detect(frame, objects + parts)
                objects_2d.add(
                    {d.label: d.box for d in truth if d.label in labels},
                    [d for d in detections if d.label in labels],
                    str,
                )
                parts_2d.add(
                    {d.label: d.box for d in truth if d.label not in labels},
                    [d for d in detections if d.label not in labels],
                    str,
                )
        return {
            "world": spec.name,
            "objects": len(objects),
            "found": len(found),
            "parts": len(parts),
            "parts_found": len({i.label for i in seen.instances} - set(labels)),
            "iou": float(np.median(ious)) if ious else 0.0,
            "center_cm": float(np.median(errors) * 100) if errors else float("nan"),
            "ious": ious,
            "errors": errors,
            "tuples_correct": float(np.mean(correct)) if correct else float("nan"),
            "objects_2d": objects_2d,
            "parts_2d": parts_2d,
            "cameras": len(frames),
            "render_s": statistics.median(render),
            "mask_s": statistics.median(mask),
            "fusion_s": statistics.median(fusion),
            "rest_s": statistics.median(rest),
            "look_s": statistics.median([sum(t) for t in zip(render, mask, fusion, rest, strict=True)]),
        }
    finally:
        backend.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--worlds", default="packaged", help="packaged, generated[:N], or world names/files")
    parser.add_argument("--detector", default="gt", help="gt (segmentation boxes) or trained[:FILE.npz]")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--robot", choices=["panda", "ur5e"], default=None, help="default: each world's robot")
    parser.add_argument("--voxel", type=float, default=0.005)
    parser.add_argument("--jitter", type=float, default=0.0, help="box edges moved by up to this fraction")
    parser.add_argument("--dropout", type=float, default=0.0, help="chance a 2D box is missed")
    args = parser.parse_args()
    settings = FusionSettings(voxel=args.voxel, truncation=4 * args.voxel)
    noise = GroundingNoise(box_jitter=args.jitter, dropout=args.dropout)
    header = (
        f"{'world':32s} {'found':>7s} {'parts':>7s} {'IoU':>5s} {'ctr cm':>6s} {'tuples':>6s} {'2D P':>5s} "
        f"{'2D R':>5s} {'render':>7s} {'robot':>6s} {'fusion':>7s} {'rest':>6s} {'look':>6s}"
    )
    print(header, flush=True)
    rows = []
    for world in resolve_worlds(args.worlds):
        r = measure(world, args, settings, noise)
        rows.append(r)
        tally = r["objects_2d"]
        print(
            f"{r['world']:32s} {r['found']:>3d}/{r['objects']:<3d} {r['parts_found']:>3d}/{r['parts']:<3d} "
            f"{r['iou']:5.2f} {r['center_cm']:6.2f} {r['tuples_correct']:6.0%} "
            f"{tally.precision:5.2f} {tally.recall:5.2f} {r['render_s']:7.3f} {r['mask_s']:6.3f} "
            f"{r['fusion_s']:7.3f} {r['rest_s']:6.3f} {r['look_s']:6.3f}",
            flush=True,
        )
    looks = [r["look_s"] for r in rows]
    ious = [v for r in rows for v in r["ious"]]
    errors = [v for r in rows for v in r["errors"]]
    print(
        f"{len(rows)} worlds: median over worlds: IoU {statistics.median(r['iou'] for r in rows):.2f}, centre error "
        f"{statistics.median(r['center_cm'] for r in rows):.2f} cm; over all {len(ious)} objects found: median IoU "
        f"{np.median(ious):.2f}, median centre error {np.median(errors) * 100:.2f} cm; objects found "
        f"{sum(r['found'] for r in rows)}/{sum(r['objects'] for r in rows)}; one look {statistics.median(looks):.3f} s "
        f"median (max {max(looks):.3f} s)"
    )
    if args.detector != "gt":
        objects, parts = Tally(), Tally()
        for r in rows:
            for total, tally in ((objects, r["objects_2d"]), (parts, r["parts_2d"])):
                total.detections += tally.detections
                total.right += tally.right
                total.objects += tally.objects
                total.found += tally.found
                total.missed.update(tally.missed)
                total.wrong.update(tally.wrong)
        print(f"2D detections, objects per view (IoU >= 0.5): {objects.line()}")
        print(f"2D detections, furniture parts per view: {parts.line()}")
        if objects.missed:
            print("  missed: " + ", ".join(f"{n} ({c})" for n, c in objects.missed.most_common(10)))
        if objects.wrong:
            print("  wrong: " + ", ".join(f"{n} ({c})" for n, c in objects.wrong.most_common(10)))


if __name__ == "__main__":
    main()
