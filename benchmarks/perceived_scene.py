"""Perceived planning scene benchmark: how often it agrees with the simulator's exact geometry on whether an arm
configuration collides, and what building it costs.

Run: python benchmarks/perceived_scene.py [--samples 1000] [--robot panda] [--mode gt-2d]

Per world: the share of uniformly sampled arm configurations on whose collision verdict the perceived scene
(built from one look) and the exact scene agree; of the disagreements, how many the perceived scene calls free
while the exact one collides (the dangerous kind: mostly surfaces no camera sees, such as a cabinet's back) and
how many the other way; the number of collision boxes; and the median time to build the scene from a look that
was already made (sorting points, occupancy boxes, compiling the model), over ``--repeats``.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.modes import parse_mode
from roboscript.planning.ground_truth_scene import ground_truth_scene
from roboscript.sim.world_catalog import world_names


def measure(world: str, robot: str, mode: str, samples: int, repeats: int) -> dict:
    backend = MujocoBackend(world, robot=robot)
    try:
        exact = ground_truth_scene(backend.sim_world)
        motion = build_tools(backend, perception=mode).motion
        scene = motion.scene
        scene.update(motion.scene_source.state())
        rng = np.random.default_rng(0)
        verdicts = np.array(
            [
                (exact.is_free(q), scene.is_free(q))
                for q in (rng.uniform(exact.joint_lower, exact.joint_upper) for _ in range(samples))
            ]
        )
        builds = []
        for _ in range(repeats):
            motion.world_changed()
            start = time.perf_counter()
            motion.scene  # noqa: B018 (the rebuild is what is timed)
            builds.append(time.perf_counter() - start)
        geoms = sum(
            1
            for g in range(scene.model.ngeom)
            if not scene.body_labels[scene.model.geom_bodyid[g]].startswith("robot/")
        )
        return {
            "world": world,
            "agree": float(np.mean(verdicts[:, 0] == verdicts[:, 1])),
            "missed": int(np.sum(verdicts[:, 1] & ~verdicts[:, 0])),
            "extra": int(np.sum(verdicts[:, 0] & ~verdicts[:, 1])),
            "colliding": int(np.sum(~verdicts[:, 0])),
            "boxes": geoms,
            "build": statistics.median(builds),
        }
    finally:
        backend.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--samples", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--robot", choices=["panda", "ur5e"], default="panda")
    parser.add_argument("--mode", default="gt-2d", help="a perception mode whose planning scene is observed")
    args = parser.parse_args()
    if not parse_mode(args.mode).observed_scene:
        parser.error(f"--mode {args.mode} takes the planning scene from ground truth; give one that observes it")
    print(f"{'world':34} {'agree':>6} {'missed':>6} {'extra':>6} {'colliding':>9} {'boxes':>6} {'build s':>8}")
    rows = []
    for world in world_names():
        row = measure(world, args.robot, args.mode, args.samples, args.repeats)
        rows.append(row)
        print(
            f"{world:34} {row['agree']:6.3f} {row['missed']:6d} {row['extra']:6d} {row['colliding']:9d} "
            f"{row['boxes']:6d} {row['build']:8.2f}",
            flush=True,
        )
    print(
        f"median agreement {statistics.median(r['agree'] for r in rows):.3f}; "
        f"median build {statistics.median(r['build'] for r in rows):.2f} s"
    )


if __name__ == "__main__":
    main()
