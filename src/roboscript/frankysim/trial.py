"""A benchmark task's trial through libfranka: franky-sim serves the task's world with the FR3 where the world stands
it, the program's tools drive the arm through franky as they would a lab's FR3, perception sees only the cameras
(rendered from a mirror of franky-sim's world), and the task's checks read that mirror afterwards, on this side,
where no tool reaches."""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field

from roboscript.assembly import build_tools
from roboscript.backends.franky import franky_backend
from roboscript.bench.task_file import Task
from roboscript.bench.trial import check_and_execute
from roboscript.codegen.sandbox import ExecutionResult, Limits
from roboscript.frankysim.launch import FrankySim
from roboscript.frankysim.mirror import MirrorCameras, WorldMirror
from roboscript.perception.modes import PerceptionMode, perception_mode
from roboscript.robot_config import RobotConfig, load_robot_config
from roboscript.sim.world_catalog import load_world

# franky-sim's arm lags its set-point by up to 0.04 rad at this speed scale and 0.1 rad at the default 0.25 (a
# real FR3 by a thousandth of that): slower motions keep the TCP within the tools' 2 cm of the plan.
FRANKY_SIM_SPEED_SCALE = 0.1
SETTLE = 1.0  # seconds of franky-sim's world after the program, before the checks read it


@dataclass
class FrankyTrial:
    """What a trial through libfranka gave: the program's result and the task's checks."""

    task: str
    seed: int
    result: ExecutionResult
    checks: list[dict] = field(default_factory=list)
    wall: float = 0.0

    @property
    def success(self) -> bool:
        return bool(self.checks) and all(c["passed"] for c in self.checks)


def franky_sim_config(host: str, speed_scale: float = FRANKY_SIM_SPEED_SCALE) -> RobotConfig:
    """The packaged FR3 configuration pointed at a franky-sim at ``host`` (no real-time kernel needed)."""
    config = load_robot_config("fr3_franky")
    settings = dataclasses.replace(config.franky, host=host, realtime=False)
    return dataclasses.replace(config, franky=settings, speed_scale=speed_scale, joint_states=f"libfranka at {host}")


def run_through_franky(
    task: Task,
    program: str,
    perception: PerceptionMode | str = "full",
    timeout: float = 600.0,
    speed_scale: float = FRANKY_SIM_SPEED_SCALE,
    seed: int = 0,
) -> FrankyTrial:
    """Runs ``program`` on ``task`` through libfranka against a franky-sim of the task's world, laid out as the
    MuJoCo backend's trial of ``seed`` lays it out; returns the program's result and the checks, read from
    franky-sim's world once it has settled."""
    started = time.monotonic()
    world = load_world(task.world).randomized(seed)
    mode = perception_mode(perception) if isinstance(perception, str) else perception
    with FrankySim(world=task.world, seed=seed) as sim:
        mirror = WorldMirror(sim, world)
        cameras = MirrorCameras(mirror)
        backend = franky_backend(franky_sim_config(sim.host, speed_scale), cameras=cameras)
        try:
            tools = build_tools(backend, mode, scene=world)
            result = check_and_execute(program, tools.namespace(), Limits(timeout).scaled_to_load())
            backend.wait(SETTLE)
            mirror.sync()
            checks = [c.evaluate(mirror.ground_truth).to_dict() for c in task.build_checks(mirror.ground_truth)]
        finally:
            backend.close()
    return FrankyTrial(task.id, seed, result, checks, time.monotonic() - started)
