"""A trial through libfranka (``--backend franky``): franky-sim serves the task's world, laid out as the MuJoCo
backend's trial of the same seed lays it out, with the FR3 where the world stands it; the program's tools drive the
arm through franky as they would a lab's FR3; perception sees only the cameras, rendered from a mirror of franky-sim's
world; and the task's checks read that mirror when the program is done, where no tool reaches.

The backend and the tools know nothing of the simulation; only this harness does (``roboscript.frankysim``).
"""

from __future__ import annotations

import dataclasses

from roboscript.bench.tasks import Task
from roboscript.bench.trial_world import TrialWorld, attempt_record
from roboscript.codegen.sandbox import ExecutionResult
from roboscript.errors import UsageError
from roboscript.perception.modes import PerceptionMode
from roboscript.robot_config import RobotConfig, franky_at, load_robot_config

# franky-sim's arm lags its set-point in proportion to the speed: by up to 0.054 rad at speed scale 0.1, which took the
# TCP 2.0 to 3.9 cm off the plan in 12 of 20 trials (the tools stop at 2 cm), and 0.028 rad at 0.05. A real FR3 lags
# by about a thousandth of that.
FRANKY_SIM_SPEED_SCALE = 0.05
SETTLE = 1.0  # seconds of franky-sim's world after the program, before the checks read it


def franky_sim_config(host: str, speed_scale: float = FRANKY_SIM_SPEED_SCALE) -> RobotConfig:
    """The packaged FR3 configuration pointed at a franky-sim at ``host`` (no real-time kernel needed)."""
    config = franky_at(load_robot_config("fr3_franky"), host, realtime=False)
    return dataclasses.replace(config, speed_scale=speed_scale)


def franky_perception(mode: PerceptionMode) -> PerceptionMode:
    """The mode a trial through libfranka runs with: the cameras alone (a lab's FR3 has no ground truth)."""
    if mode.from_truth:
        raise UsageError(
            f"perception {mode} takes {', '.join(sorted(mode.from_truth))} from ground truth, which a robot does not "
            "have: through libfranka use full"
        )
    return mode


class FrankyTrialWorld(TrialWorld):
    """One attempt's world served by franky-sim, the tools driving its FR3 through libfranka."""

    sim = cameras = None

    def __init__(self, spec, task: Task):
        if spec.robot != "fr3":
            raise UsageError(f"--backend franky drives an FR3 through libfranka: pass --robot fr3 (got {spec.robot})")
        if spec.video or spec.record:
            raise UsageError("--video and --record are not taken through libfranka; run the mujoco backend for them")
        super().__init__(spec, task)

    def build(self) -> None:
        from roboscript.assembly import build_tools
        from roboscript.backends.franky import franky_backend
        from roboscript.frankysim.launch import FrankySim  # the franky extra's
        from roboscript.frankysim.mirror import MirrorCameras, WorldMirror
        from roboscript.sim.world_catalog import load_world

        spec = self.spec
        world = load_world(self.task.world).randomized(spec.seed)
        self.sim = FrankySim(world=self.task.world, seed=spec.seed)
        self.mirror = WorldMirror(self.sim, world)
        self.cameras = MirrorCameras(self.mirror)
        self.backend = franky_backend(franky_sim_config(self.sim.host), cameras=self.cameras)
        tools = build_tools(self.backend, franky_perception(spec.perception), seed=spec.seed, scene=world)
        self.namespace = tools.namespace()

    def judge(self, result: ExecutionResult) -> dict:
        self.backend.wait(SETTLE)
        self.mirror.sync()
        truth = self.mirror.ground_truth
        checks = [c.evaluate(truth).to_dict() for c in self.task.build_checks(truth)] if self.spec.world is None else []
        return attempt_record(result, checks, self.backend.time() - self.sim_start)

    def close(self, built: bool) -> None:
        if self.backend is not None:
            self.backend.close()
        if self.cameras is not None:
            self.cameras.close()
        if self.sim is not None:
            self.sim.stop()
