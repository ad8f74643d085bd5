"""Helpers for tests: worlds built from dicts, a driver test double, a small IK used only to script joint
targets in tests, and how a sweep's trials ended.

The project's own IK belongs to the planning layer; this damped-least-squares solver exists so that foundation
tests can compute joint waypoints without depending on it.
"""

from __future__ import annotations

import importlib.util
import json
import time
from itertools import pairwise
from pathlib import Path

import mujoco
import numpy as np
import pytest

from roboscript.drivers.base import Driver
from roboscript.geometry import matrix_to_quat
from roboscript.sim.world import SimWorld
from roboscript.trajectory import JointTrajectory, scaled_limits

# Every arm; the FR3's model comes with the franky extra, and its cases are skipped where that is not installed.
ARMS = (
    "panda",
    "ur5e",
    pytest.param(
        "fr3",
        marks=pytest.mark.skipif(
            importlib.util.find_spec("franky_sim") is None, reason="the FR3's model comes with the franky extra"
        ),
    ),
)

class ArmOnlyDriver(Driver):
    """Test double of a driver with an arm and nothing else: the host's monotonic clock, no cameras, and neither
    trajectories nor a gripper unless a subclass gives them; subclasses say what the joint states read."""

    def now(self) -> float:
        return time.monotonic()

    def send_trajectory(self, joint_names, trajectory):
        raise NotImplementedError

    def command_gripper(self, position, closing, timeout):
        raise NotImplementedError

    def camera_names(self) -> list[str]:
        return []

    def camera_frame(self, camera, timeout, not_before):
        raise NotImplementedError


DOWN = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])  # TCP z pointing at the table
DOWN_QUAT = matrix_to_quat(DOWN)


def tcp_ik(world: SimWorld, position, rotation=DOWN, q0=None, iterations: int = 300) -> np.ndarray:
    """Arm configuration putting the TCP at ``position`` with ``rotation`` (test helper, DLS IK)."""
    m = world.model
    d = mujoco.MjData(m)
    d.qpos[:] = world.data.qpos
    r = world.robot
    if q0 is not None:
        d.qpos[r.qpos] = q0
    jacp, jacr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
    target_rot = np.asarray(rotation)
    for _ in range(iterations):
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        pos = d.site_xpos[r.tcp_site]
        rot = d.site_xmat[r.tcp_site].reshape(3, 3)
        err_p = np.asarray(position) - pos
        err_r = 0.5 * sum(np.cross(rot[:, i], target_rot[:, i]) for i in range(3))
        err = np.concatenate([err_p, err_r])
        if np.linalg.norm(err_p) < 1e-4 and np.linalg.norm(err_r) < 1e-3:
            break
        mujoco.mj_jacSite(m, d, jacp, jacr, r.tcp_site)
        jac = np.vstack([jacp, jacr])[:, r.dof]
        dq = jac.T @ np.linalg.solve(jac @ jac.T + 1e-4 * np.eye(6), err)
        dq *= min(1.0, 0.2 / max(np.max(np.abs(dq)), 1e-12))  # small steps keep it on the seed's branch
        d.qpos[r.qpos] = np.clip(d.qpos[r.qpos] + dq, r.joint_lower, r.joint_upper)
    else:
        raise AssertionError(f"test IK did not converge to {position}: error {np.linalg.norm(err_p):.4f} m")
    q = d.qpos[r.qpos].copy()
    seed = world.data.qpos[r.qpos] if q0 is None else np.asarray(q0)
    # Joints that turn more than one revolution: take the solution's equivalent angle nearest the seed.
    wrapped = seed + (q - seed + np.pi) % (2 * np.pi) - np.pi
    ok = (wrapped >= r.joint_lower) & (wrapped <= r.joint_upper)
    return np.where(ok, wrapped, q)


def stack_on(tools: dict, thing: str, base: str, lift: float = 0.1) -> None:
    """Runs the tools (a namespace of :func:`roboscript.assembly.build_tools`) to take ``thing`` from above, lift it
    ``lift`` metres, put it on ``base`` and back off 10 cm, as a program stacking one thing on another would."""
    tools["open_gripper"]()
    tools["grasp"](tools["parse_central_lift_grasp_pose"](object_name=thing, description="center"))
    tools["close_gripper"]()
    tools["attach_object"](thing)
    tools["move_in_direction"]([0, 0, 1], lift)
    tools["move_to_pose"](tools["parse_place_pose"](object_name=thing, receptacle_name=base))
    tools["open_gripper"]()
    tools["detach_object"](thing)
    tools["move_in_direction"]([0, 0, 1], 0.1)


# Peak speed and acceleration of the quintic rest-to-rest profile s(u) = 10u^3 - 15u^4 + 6u^5, per unit distance
# and unit time.
MIN_JERK_PEAK_VELOCITY = 1.875
MIN_JERK_PEAK_ACCELERATION = 5.7735


def min_jerk_through(
    waypoints: np.ndarray,
    max_velocity: np.ndarray,
    max_acceleration: np.ndarray,
    speed_scale: float = 1.0,
    sample_dt: float = 0.01,
) -> JointTrajectory:
    """Test data: a rest-to-rest quintic (minimum-jerk) motion through each waypoint in turn, for tests that drive
    an arm without a planner.

    Each segment lasts long enough that no joint exceeds ``speed_scale`` times its velocity and acceleration
    limits. The result is sampled every ``sample_dt`` seconds.
    """
    waypoints = np.atleast_2d(np.asarray(waypoints, dtype=float))
    if len(waypoints) < 2:
        raise ValueError("min_jerk_through needs at least two waypoints")
    vmax, amax = scaled_limits(max_velocity, max_acceleration, speed_scale)
    times, positions, velocities = [0.0], [waypoints[0]], [np.zeros(waypoints.shape[1])]
    t0 = 0.0
    for a, b in pairwise(waypoints):
        delta = b - a
        dist = np.abs(delta)
        duration = float(
            max(
                np.max(MIN_JERK_PEAK_VELOCITY * dist / vmax),
                np.max(np.sqrt(MIN_JERK_PEAK_ACCELERATION * dist / amax)),
                sample_dt,
            )
        )
        n = max(2, int(np.ceil(duration / sample_dt)))
        for k in range(1, n + 1):
            u = k / n
            s = 10 * u**3 - 15 * u**4 + 6 * u**5
            ds = (30 * u**2 - 60 * u**3 + 30 * u**4) / duration
            times.append(t0 + u * duration)
            positions.append(a + s * delta)
            velocities.append(ds * delta)
        t0 += duration
    return JointTrajectory(np.array(times), np.array(positions), np.array(velocities))


def sweep_outcomes(run_dir: Path) -> dict:
    """Per (task, trial) of a run directory: its seed, how it ended and which checks passed. Not the simulated
    time: a planner stops at its first path, and which one it finds first depends on how fast the machine is at
    that moment."""
    out = {}
    for line in (run_dir / "results.jsonl").read_text().splitlines():
        r = json.loads(line)
        out[(r["task"], r["trial"])] = (r["seed"], r["outcome"], [c["passed"] for c in r["checks"]])
    return out
