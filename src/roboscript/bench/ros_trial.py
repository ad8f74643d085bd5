"""A trial through ROS: the task's world served by `roboscript ros-sim` (its own rosmaster, on a free port), the
program's tools on the ROS backend with perception from the cameras and the robot's segmentation topic, and the
task's checks evaluated by the twin on its own state when the program is done.

The backend and the tools know nothing of the simulation; only this harness does, to start it and to ask it for the
verdict.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile

from roboscript.bench.trial_world import TrialWorld, attempt_record
from roboscript.codegen.sandbox import ExecutionResult
from roboscript.errors import InvalidArgumentError
from roboscript.perception.modes import SEGMENTATION, PerceptionMode, perception_mode
from roboscript.processes import at_process_exit
from roboscript.robot_config import ros_config_for

REAL_TIME_FACTOR = 2.0
_MASTER: tuple | None = None  # (process, uri, home): one per process, as this process's ROS node is bound to it


def _process_master() -> str:
    """This process's rosmaster, started at its first ROS trial; it ends with the process (see
    :func:`roboscript.ros.launch.start_master`)."""
    global _MASTER
    if _MASTER is None or _MASTER[0].poll() is not None:
        from roboscript.ros.launch import start_master

        home = tempfile.mkdtemp(prefix="roboscript_ros_")
        process, uri = start_master(home)
        _MASTER = (process, uri, home)
        at_process_exit(lambda: _stop_master(process, home))  # a trial's process runs these before it leaves
        os.environ.update(ROS_MASTER_URI=uri, ROS_IP="127.0.0.1", ROS_HOME=home)
    return _MASTER[1]


def _stop_master(process, home: str) -> None:
    """Stops this process's master and removes its ROS home (its logs)."""
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            process.kill()
    shutil.rmtree(home, ignore_errors=True)


def ros_perception(mode: PerceptionMode) -> PerceptionMode:
    """The mode a ROS trial runs with: everything from the robot's sensors; its 2D boxes from the segmentation topic
    unless a detector was given."""
    if mode.from_truth - {"2d"}:
        raise InvalidArgumentError(
            f"perception {mode} takes {', '.join(sorted(mode.from_truth))} from ground truth, which a robot does not "
            "have: through ROS use full (or gt-2d, which reads the robot's segmentation topic)"
        )
    return mode if mode.detector is not None else perception_mode("full", SEGMENTATION)


class RosTrialWorld(TrialWorld):
    """One attempt's world served by ros-sim, the tools on the ROS backend."""

    sim = None

    def build(self) -> None:
        from roboscript.assembly import build_tools
        from roboscript.backends.ros import ros_backend
        from roboscript.ros.launch import start_sim
        from roboscript.sim.world_catalog import load_world

        spec = self.spec
        if spec.video:
            raise InvalidArgumentError(
                "--video is not recorded through ROS yet; record the twin with the mujoco backend"
            )
        uri = _process_master()
        self.sim = start_sim(
            self.task.world,
            spec.robot,
            uri,
            REAL_TIME_FACTOR,
            seed=spec.seed,
            randomize=True,
            task=self.task.id if spec.world is None else None,
            suite=spec.suite,
        )
        self.backend = ros_backend(spec.robot_config or ros_config_for(spec.robot))
        mode = ros_perception(spec.perception)
        tools = build_tools(self.backend, mode, seed=spec.seed, scene=load_world(self.task.world))
        self.namespace = tools.namespace()

    def judge(self, result: ExecutionResult) -> dict:
        from roboscript.ros.launch import evaluate_on_twin

        self.backend.wait(1.0)
        checks = evaluate_on_twin() if self.spec.world is None else []
        return attempt_record(result, checks, self.backend.time() - self.sim_start)

    def close(self, built: bool) -> None:
        if self.backend is not None:
            self.backend.close()
        if self.sim is not None:
            self.sim.stop()
