"""Real-time factor of each world with the controller active (no rendering), and time per camera frame.

Run: python benchmarks/sim_speed.py [--seconds 10] [--repeats 3] [--robots panda,ur5e]

The arm follows a scripted joint trajectory (a sinusoid about home) through the real controller; the figure is
simulated seconds per wall second, the median over repeats. Camera time is for RGB + depth + segmentation of
one 640x480 camera, median over every camera and repeat. MuJoCo runs on one core.

Objects at rest sleep (MuJoCo's island sleeping, enabled in every world); the "all awake" column repeats the
run with sleeping disabled, which is the cost when everything on the table is in motion at once.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.sim.world_catalog import world_names
from roboscript.trajectory import JointTrajectory


def sinusoid_about_home(home: np.ndarray, seconds: float, amplitude: float = 0.25) -> JointTrajectory:
    times = np.arange(0.0, seconds + 1e-9, 0.02)
    phase = 2 * np.pi * 0.25 * times[:, None] + np.arange(len(home))[None, :]
    ramp = np.clip(times / 1.0, 0, 1)[:, None]  # starts at rest, at home
    positions = home + ramp * amplitude * (np.sin(phase) - np.sin(np.arange(len(home))))
    velocities = np.gradient(positions, times, axis=0)
    return JointTrajectory(times, positions, velocities)


def real_time_factor(world: str, robot: str, seconds: float, sleep: bool) -> tuple[float, float, MujocoBackend]:
    backend = MujocoBackend(world, robot=robot, settle=0.0)
    backend.simulator.sleeping_enabled = sleep
    backend.simulator.settle(1.0)
    trajectory = sinusoid_about_home(backend.joint_positions(), seconds)
    start = time.perf_counter()
    report = backend.simulator.execute(trajectory, settle=0.0)
    return report.duration / (time.perf_counter() - start), report.max_tcp_error, backend


def measure(world: str, robot: str, seconds: float, repeats: int) -> tuple[float, float, float, float]:
    factors, awake_factors, frames, errors = [], [], [], []
    for _ in range(repeats):
        awake_factor, _, awake_backend = real_time_factor(world, robot, seconds, sleep=False)
        awake_backend.close()
        awake_factors.append(awake_factor)
        factor, error, backend = real_time_factor(world, robot, seconds, sleep=True)
        factors.append(factor)
        errors.append(error)
        for camera in backend.camera_names():
            backend.capture(camera)  # the first capture creates the renderer; time the next ones
            start = time.perf_counter()
            backend.capture(camera)
            frames.append(time.perf_counter() - start)
        backend.close()
    return statistics.median(factors), statistics.median(awake_factors), statistics.median(frames), max(errors)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seconds", type=float, default=10.0, help="simulated seconds per run")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--robots", default="panda,ur5e")
    args = parser.parse_args()
    header = ("world", "robot", "real-time x", "all awake x", "ms/camera", "max TCP err mm")
    print(f"{header[0]:34s} {header[1]:6s} {header[2]:>12s} {header[3]:>12s} {header[4]:>10s} {header[5]:>15s}")
    all_factors, all_awake = [], []
    for world in world_names():
        for robot in args.robots.split(","):
            factor, awake, frame, error = measure(world, robot, args.seconds, args.repeats)
            all_factors.append(factor)
            all_awake.append(awake)
            print(
                f"{world:34s} {robot:6s} {factor:12.1f} {awake:12.1f} {frame * 1000:10.1f} {error * 1000:15.2f}",
                flush=True,
            )
    print(
        f"median real-time factor over worlds and robots: {statistics.median(all_factors):.1f}x "
        f"(min {min(all_factors):.1f}x); all awake: median {statistics.median(all_awake):.1f}x "
        f"(min {min(all_awake):.1f}x); target: 30x on one core"
    )


if __name__ == "__main__":
    main()
