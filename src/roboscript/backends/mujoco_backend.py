"""The MuJoCo simulation backend."""

from __future__ import annotations

import numpy as np

from roboscript.backends.base import Backend, BackendError
from roboscript.geometry import Transform, matrix_to_quat
from roboscript.robots import RobotDescription
from roboscript.sim.cameras import CameraFrame, Renderer
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.simulator import ExecutionReport, GripperReport, Simulator
from roboscript.sim.trajectory import JointTrajectory
from roboscript.sim.world import SimWorld, build_world
from roboscript.sim.world_catalog import load_world
from roboscript.sim.world_file import WorldSpec


class MujocoBackend(Backend):
    """A simulated robot in a world built from a world file.

    Args:
        world: a world name from the catalogue, a path to a world file, or a parsed :class:`WorldSpec`.
        robot: ``panda`` or ``ur5e``; default: the world's own.
        seed: seeds pose randomisation (only used when ``randomize`` is true).
        randomize: jitter object poses by the world's ``randomize`` amounts.
        settle: simulated seconds to let the world come to rest before anything else happens.
    """

    def __init__(
        self,
        world: str | WorldSpec,
        robot: str | None = None,
        seed: int = 0,
        randomize: bool = False,
        settle: float = 1.0,
    ):
        spec = world if isinstance(world, WorldSpec) else load_world(world)
        if randomize:
            spec = spec.randomized(seed)
        self.sim_world: SimWorld = build_world(spec, robot)
        self.simulator = Simulator(self.sim_world)
        self._ground_truth = GroundTruth(self.sim_world)
        self._renderers: dict[tuple[int, int], Renderer] = {}
        self._cameras = {c.name: c for c in spec.cameras}
        if settle > 0:
            self.simulator.settle(settle)

    @property
    def robot(self) -> RobotDescription:
        return self.sim_world.robot.description

    def joint_positions(self) -> np.ndarray:
        return self.simulator.joint_positions()

    def tcp_pose(self) -> Transform:
        return Transform(self.simulator.tcp_position(), matrix_to_quat(self.simulator.tcp_rotation()))

    def gripper_width(self) -> float:
        return self.simulator.gripper_width()

    def time(self) -> float:
        return self.simulator.time

    def execute_trajectory(self, trajectory: JointTrajectory) -> ExecutionReport:
        try:
            return self.simulator.execute(trajectory)
        except ValueError as exc:  # joint count, start configuration, joint limits
            raise BackendError(str(exc)) from exc

    def set_gripper(self, closed: float) -> GripperReport:
        return self.simulator.set_gripper(closed)

    def wait(self, seconds: float) -> None:
        self.simulator.step(seconds)

    def camera_names(self) -> list[str]:
        return list(self._cameras)

    def renderer(self, width: int, height: int) -> Renderer:
        """A renderer of the given size, created once and reused."""
        key = (width, height)
        if key not in self._renderers:
            self._renderers[key] = Renderer(self.sim_world.model, self.sim_world.geom_entity, width, height)
        return self._renderers[key]

    def capture(self, camera: str) -> CameraFrame:
        if camera not in self._cameras:
            raise BackendError(f"no camera named {camera!r}; cameras: {', '.join(self._cameras)}")
        spec = self._cameras[camera]
        return self.renderer(spec.width, spec.height).capture(self.sim_world.data, camera, spec)

    @property
    def ground_truth(self) -> GroundTruth:
        return self._ground_truth

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()
