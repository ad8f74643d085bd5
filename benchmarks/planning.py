"""Motion-planning benchmark: success rate and planning time per planner, on fixed seeded queries, both arms.

Run: python benchmarks/planning.py [--queries 100] [--planners RRTConnect,RRTstar,...|all] [--others 20]
                                   [--timeout 2] [--out results.jsonl]

Queries are made in the benchmark worlds with a table and a cabinet (worlds 1 and 5): goals are TCP poses, half
top-down over the table area, half horizontal in front of the cabinet's handles; a query is feasible when
collision-free IK finds a goal configuration. Each query starts where the previous one ended, so starts vary too.
RRTConnect gets ``--queries`` queries per arm, every other planner the first ``--others``.

Each query is planned as the product plans (``MotionPlanner.plan``): a planner that runs out of ``--timeout``
tries again with twice the time, up to three runs. Success is counted after those retries; 'first' is the share
found by the first run alone, the figure a single-shot planner would give. PRM and PRM* are OMPL's roadmaps grown
and queried in the calling thread (:mod:`roboscript.planning.roadmap`): OMPL's own ``PRM::solve`` deadlocked this
benchmark on the GIL, its second thread running the Python collision check.

For each returned path: planning time (OMPL solve + simplification), validation time (dense check at the scene's
5 mm padding), and an independent exact check (no padding, 1 mm steps of any point of the arm) that counts paths
in collision. Each result is printed, and appended to ``--out`` as a JSON line, as soon as it exists.
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from dataclasses import dataclass

import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform, matrix_to_quat
from roboscript.planning import PlanningError, planner_names
from roboscript.planning.errors import PathInCollisionError
from roboscript.planning.ground_truth_scene import ground_truth_motion, ground_truth_scene
from roboscript.planning.planner import JointPlanner

WORLDS = ("world_1_table_sort", "world_5_mug_to_cabinet")
TABLE = 0.82


@dataclass(frozen=True)
class Query:
    world: str
    start: np.ndarray
    goal: np.ndarray
    kind: str


def top_down(yaw: float) -> np.ndarray:
    c, s = np.cos(yaw), np.sin(yaw)
    return matrix_to_quat(np.array([[c, s, 0.0], [s, -c, 0.0], [0.0, 0.0, -1.0]]))


def towards_cabinet(alpha: float) -> np.ndarray:
    approach = np.array([-np.cos(alpha), np.sin(alpha), 0.0])
    closing = np.array([0.0, 0.0, 1.0])
    return matrix_to_quat(np.column_stack([np.cross(closing, approach), closing, approach]))


def make_queries(robot: str, count: int, seed: int) -> list[Query]:
    rng = np.random.default_rng(seed)
    queries: list[Query] = []
    per_world = int(np.ceil(count / len(WORLDS)))
    for world in WORLDS:
        backend = MujocoBackend(world, robot=robot, settle=0.5)
        motion = ground_truth_motion(backend)
        handles = [n for n in backend.ground_truth.names() if ".handle_" in n]
        start = backend.joint_positions()
        made = 0
        while made < per_world:
            if made % 2 == 0:
                position = np.array([rng.uniform(-0.3, 0.25), rng.uniform(-0.45, 0.45), TABLE + rng.uniform(0.1, 0.35)])
                pose, kind = Transform(position, top_down(rng.uniform(-np.pi / 2, np.pi / 2))), "table"
            else:
                handle = backend.ground_truth.box(handles[int(rng.integers(len(handles)))]).center
                alpha = rng.uniform(0.5, 0.9)
                approach = np.array([-np.cos(alpha), np.sin(alpha), 0.0])
                pose, kind = Transform(handle - rng.uniform(0.05, 0.15) * approach, towards_cabinet(alpha)), "cabinet"
            try:
                goal = motion.ik(pose, start)
            except PlanningError:
                continue  # infeasible: not a query
            queries.append(Query(world, start, goal, kind))
            start, made = goal, made + 1
        backend.close()
    return queries[:count]


def run(robot: str, planners: list[str], count: int, others: int, timeout: float, seed: int, out) -> dict:
    queries = make_queries(robot, count, seed)
    summary = {}
    for planner in planners:
        subset = queries if planner == "RRTConnect" else queries[:others]
        times, totals, failures, in_collision, first = [], [], 0, 0, 0
        for world in WORLDS:
            world_queries = [q for q in subset if q.world == world]
            if not world_queries:
                continue
            backend = MujocoBackend(world, robot=robot, settle=0.5)
            motion = ground_truth_motion(backend)
            exact = JointPlanner(ground_truth_scene(backend.sim_world, padding=0.0), validation_step=0.001)
            for index, query in enumerate(world_queries):
                record = {"robot": robot, "planner": planner, "world": world, "query": index, "kind": query.kind}
                try:
                    path = motion.plan(query.start, [query.goal], planner=planner, timeout=timeout)
                except PlanningError as error:
                    failures += 1
                    record.update(ok=False, error=str(error))
                else:
                    first += path.attempts == 1
                    times.append(path.planning_time)
                    totals.append(path.planning_time + path.validation_time)
                    try:
                        exact.validate(path.waypoints)
                        collides = False
                    except PathInCollisionError:
                        collides, in_collision = True, in_collision + 1
                    record.update(
                        ok=True,
                        planning_ms=path.planning_time * 1000,
                        validation_ms=path.validation_time * 1000,
                        waypoints=len(path.waypoints),
                        replans=path.replans,
                        attempts=path.attempts,
                        in_collision=collides,
                    )
                if out is not None:
                    out.write(json.dumps(record) + "\n")
                    out.flush()
            backend.close()
        n = len(subset)
        row = {
            "queries": n,
            "success": (n - failures) / n if n else float("nan"),
            "first_attempt": first / n if n else float("nan"),
            "median_ms": statistics.median(times) * 1000 if times else float("nan"),
            "p95_ms": float(np.percentile(times, 95)) * 1000 if times else float("nan"),
            "median_total_ms": statistics.median(totals) * 1000 if totals else float("nan"),
            "in_collision": in_collision,
        }
        summary[planner] = row
        print(
            f"{robot:6s} {planner:16s} {row['queries']:5d} {row['success'] * 100:8.1f}% "
            f"{row['first_attempt'] * 100:6.1f}% {row['median_ms']:10.1f} "
            f"{row['p95_ms']:9.1f} {row['median_total_ms']:12.1f} {row['in_collision']:10d}",
            flush=True,
        )
    return summary


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--queries", type=int, default=100, help="RRTConnect queries per arm")
    parser.add_argument("--others", type=int, default=20, help="queries per arm for every other planner")
    parser.add_argument("--planners", default="all", help="comma-separated names, or 'all'")
    parser.add_argument("--robots", default="panda,ur5e")
    parser.add_argument("--timeout", type=float, default=2.0, help="seconds of a query's first planner run")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default=None, help="append one JSON line per query to this file")
    args = parser.parse_args()
    planners = planner_names() if args.planners == "all" else args.planners.split(",")
    if "RRTConnect" in planners:
        planners.remove("RRTConnect")
        planners.insert(0, "RRTConnect")
    out = open(args.out, "a") if args.out else None  # noqa: SIM115 (closed below; appended to as results come)
    print(
        f"{'robot':6s} {'planner':16s} {'n':>5s} {'success':>9s} {'first':>7s} {'median ms':>10s} {'p95 ms':>9s} "
        f"{'+validation':>12s} {'colliding':>10s}"
    )
    began = time.perf_counter()
    try:
        for robot in args.robots.split(","):
            run(robot, planners, args.queries, args.others, args.timeout, args.seed, out)
    finally:
        if out is not None:
            out.close()
    print(
        f"({time.perf_counter() - began:.0f} s; 'success' after the planner's retries, 'first' by its first run; "
        "times: OMPL solve + simplification of the run that found the path; '+validation' adds the dense check; "
        "'colliding': paths found in collision by the exact 1 mm check)"
    )


if __name__ == "__main__":
    main()
