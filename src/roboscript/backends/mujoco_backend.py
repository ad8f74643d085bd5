"""The MuJoCo simulation backend."""

from __future__ import annotations

import mujoco
import numpy as np

from roboscript.backends.base import Backend, BackendError, ClockListener
from roboscript.geometry import Transform, matrix_to_quat
from roboscript.robot_io import CameraFrame, ExecutionReport, GripperReport
from roboscript.robots import ROBOT_PREFIX, RobotDescription
from roboscript.sim.cameras import Renderer
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.simulator import Simulator
from roboscript.sim.world import SimWorld, build_world, robot_joint_readings, robot_mount
from roboscript.sim.world_catalog import load_world
from roboscript.sim.world_file import WorldSpec
from roboscript.trajectory import JointTrajectory


class MujocoBackend(Backend):
    """A simulated robot in a world built from a world file.

    Args:
        world: a world name from the catalogue, a path to a world file, or a parsed :class:`WorldSpec`.
        robot: ``panda`` or ``ur5e``; default: the world's own.
        seed: seeds pose randomisation (only used when ``randomize`` is true).
        randomize: jitter object poses by the world's ``randomize`` amounts.
        settle: simulated seconds to let the world come to rest before anything else happens.
        start: the arm's joint positions to start from (a twin of a real robot starts where the robot is);
            default: the robot's home.
    """

    def __init__(
        self,
        world: str | WorldSpec,
        robot: str | None = None,
        seed: int = 0,
        randomize: bool = False,
        settle: float = 1.0,
        start: np.ndarray | None = None,
    ):
        spec = world if isinstance(world, WorldSpec) else load_world(world)
        if randomize:
            spec = spec.randomized(seed)
        self.sim_world: SimWorld = build_world(spec, robot)
        self.simulator = Simulator(self.sim_world)
        self._ground_truth = GroundTruth(self.sim_world)
        self._renderers: dict[tuple[int, int, bool], Renderer] = {}  # (width, height, colour)
        self._cameras = {c.name: c for c in spec.cameras}
        self._read_joints = robot_joint_readings(self.sim_world)
        self._base_pose = robot_mount(spec, self.sim_world.robot.description)
        self._listening = False
        if start is not None:
            self._start_at(np.asarray(start, dtype=float))
        if settle > 0:
            self.simulator.settle(settle)

    def _start_at(self, q: np.ndarray) -> None:
        binding = self.sim_world.robot
        if q.shape != (len(binding.qpos),):
            raise ValueError(
                f"start: expected {len(binding.qpos)} joint positions for the {self.robot.name}, got shape {q.shape}"
            )
        if np.any(q < binding.joint_lower - 1e-6) or np.any(q > binding.joint_upper + 1e-6):
            raise ValueError(
                f"start: joint positions {np.round(q, 3).tolist()} are outside the {self.robot.name}'s limits"
            )
        self.sim_world.data.qpos[binding.qpos] = q
        self.sim_world.data.qvel[binding.dof] = 0.0
        self.simulator.hold(q)
        mujoco.mj_forward(self.sim_world.model, self.sim_world.data)

    @property
    def robot(self) -> RobotDescription:
        return self.sim_world.robot.description

    def joint_positions(self) -> np.ndarray:
        return self.simulator.joint_positions()

    def joint_states(self) -> dict[str, float]:
        return {name.removeprefix(ROBOT_PREFIX): value for name, value in self._read_joints().items()}

    def base_pose(self) -> Transform:
        return self._base_pose

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

    def renderer(self, width: int, height: int, color: bool = True) -> Renderer:
        """A renderer of the given size, created once and reused. One for depth and segmentation only
        (``color`` false) renders without anti-aliasing, faster, unless one for colour is there already."""
        smooth = self._renderers.get((width, height, True))
        if smooth is not None:  # it renders depth and segmentation as well as the other would
            return smooth
        key = (width, height, color)
        if key not in self._renderers:
            self._renderers[key] = Renderer(self.sim_world.model, self.sim_world.geom_entity, width, height, color)
        return self._renderers[key]

    def capture(self, camera: str, color: bool = True, segmentation: bool = True) -> CameraFrame:
        if camera not in self._cameras:
            raise BackendError(f"no camera named {camera!r}; cameras: {', '.join(self._cameras)}")
        spec = self._cameras[camera]
        renderer = self.renderer(spec.width, spec.height, color)
        return renderer.capture(self.sim_world.data, camera, spec, segmentation=segmentation, color=color)

    def segmentation_labels(self) -> dict[int, str]:
        return {e.index: e.name for e in self.sim_world.entities}

    def render(self, camera: str, width: int, height: int) -> np.ndarray:
        """Renders any camera of the model (the rig's, and ``overview``) at the size asked for."""
        model = self.sim_world.model
        names = [model.cam(i).name for i in range(model.ncam)]
        if camera not in names:
            raise BackendError(f"no camera named {camera!r} to render; cameras: {', '.join(names)}")
        return self.renderer(width, height).rgb(self.sim_world.data, camera)

    def add_clock_listener(self, listener: ClockListener) -> None:
        super().add_clock_listener(listener)
        if not self._listening:  # a step callback costs every control tick: only while someone listens
            self.simulator.add_step_callback(self._on_step)
            self._listening = True

    def remove_clock_listener(self, listener: ClockListener) -> None:
        super().remove_clock_listener(listener)
        if self._listening and not self.__dict__.get("_clock_listeners"):
            self.simulator.remove_step_callback(self._on_step)
            self._listening = False

    def _on_step(self, simulator: Simulator) -> None:
        self._clock_advanced(simulator.time)

    @property
    def ground_truth(self) -> GroundTruth:
        return self._ground_truth

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()
