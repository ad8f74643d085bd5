"""Round trips through ROS against the direct MuJoCo backend: reading the joint states, and a short trajectory.

Starts a rosmaster on a free loopback port and `roboscript ros-sim` at a real-time factor of 1 (as a real arm), then
prints medians: the time to read the joint states (a cached message on ROS), the interval between joint-state
messages, and the wall time of a 0.2 s trajectory sent, executed and reported (less the trajectory's own duration:
the overhead), with the direct backend's figures beside them (it runs the same trajectory as fast as it can).

    python benchmarks/ros_latency.py [--repeats 30]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.planning.timing import time_parameterize
from roboscript.trajectory import JointTrajectory

WORLD = "world_2_pick_and_place"


def _short(backend, sign: float) -> JointTrajectory:
    q = backend.joint_positions()
    robot = backend.robot
    target = q.copy()
    target[0] += sign * 0.05
    return time_parameterize(np.array([q, target]), np.array(robot.max_velocity), np.array(robot.max_acceleration), 0.5)


def _measure(backend, repeats: int) -> dict[str, float]:
    reads, trips, overheads = [], [], []
    for _ in range(repeats):
        started = time.perf_counter()
        backend.joint_states()
        reads.append(time.perf_counter() - started)
    for k in range(repeats):
        trajectory = _short(backend, 1.0 if k % 2 == 0 else -1.0)
        started = time.perf_counter()
        backend.execute_trajectory(trajectory)
        trips.append(time.perf_counter() - started)
        overheads.append(trips[-1] - trajectory.duration)
    return {
        "joint-state read (ms)": 1000 * statistics.median(reads),
        "0.2 s trajectory round trip (ms)": 1000 * statistics.median(trips),
        "  less its duration (ms)": 1000 * statistics.median(overheads),
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=int, default=30)
    args = parser.parse_args()

    with MujocoBackend(WORLD, robot="panda") as direct:
        direct_figures = _measure(direct, args.repeats)

    from roboscript.backends.ros import ros_backend
    from roboscript.ros.launch import start_master, start_sim

    master, uri = start_master()
    os.environ["ROS_MASTER_URI"] = uri
    sim = start_sim(WORLD, "panda", uri, real_time_factor=1.0, extra=("--camera-rate", "0.2"))
    try:
        with ros_backend("panda_franka_ros") as ros:
            stamps = []
            for _ in range(200):
                reading = ros.driver.joint_state()
                if not stamps or reading.received != stamps[-1]:
                    stamps.append(reading.received)
                time.sleep(0.002)
            intervals = np.diff(stamps)
            ros_figures = _measure(ros, args.repeats)
    finally:
        sim.stop()
        master.terminate()
    print(f"{'median':36s} {'direct':>10s} {'ROS':>10s}")
    for key in direct_figures:
        print(f"{key:36s} {direct_figures[key]:10.3f} {ros_figures[key]:10.3f}")
    print(f"{'joint-state interval (ms)':36s} {'-':>10s} {1000 * float(np.median(intervals)):10.3f}")


if __name__ == "__main__":
    main()
