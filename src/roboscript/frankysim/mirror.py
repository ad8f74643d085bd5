"""A mirror of the world franky-sim runs, on this side of the wire: the same world built here, set to franky-sim's
joint positions whenever it is asked to look. Its cameras render what franky-sim's world shows (the RGB-D frames a
lab's cameras would take), and its ground truth is what a benchmark's checks read. Nothing of it reaches a program's
tools but the camera frames."""

from __future__ import annotations

import mujoco

from roboscript.drivers.base import CameraSource, DriverError
from roboscript.frankysim.launch import FrankySim
from roboscript.robot_io import CameraFrame
from roboscript.sim.cameras import Renderer
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.world import SimWorld, build_world
from roboscript.sim.world_file import WorldSpec


class WorldMirror:
    """``world`` (the one franky-sim was started with) built here, kept in step with ``sim`` on :meth:`sync`."""

    def __init__(self, sim: FrankySim, world: WorldSpec):
        self.sim, self.spec = sim, world
        self.world: SimWorld = build_world(world, "fr3")
        self.ground_truth = GroundTruth(self.world)

    def sync(self) -> None:
        """Takes franky-sim's joint positions and velocities now."""
        qpos, qvel = self.sim.state()
        if qpos.shape != self.world.data.qpos.shape:
            raise DriverError(
                f"franky-sim's world has {qpos.size} joint positions and this mirror {self.world.data.qpos.size}: "
                "they were not built from the same world"
            )
        self.world.data.qpos[:], self.world.data.qvel[:] = qpos, qvel
        mujoco.mj_forward(self.world.model, self.world.data)


class MirrorCameras(CameraSource):
    """The world's RGB-D cameras, rendered from the mirror after taking franky-sim's state (no segmentation: a
    real camera gives none)."""

    def __init__(self, mirror: WorldMirror):
        self._mirror = mirror
        self._specs = {c.name: c for c in mirror.spec.cameras}
        self._renderers: dict[tuple[int, int], Renderer] = {}

    def names(self) -> list[str]:
        return list(self._specs)

    def frame(self, camera: str, timeout: float, not_before: float) -> CameraFrame:
        if camera not in self._specs:
            raise DriverError(f"no camera {camera!r} in the mirrored world; cameras: {', '.join(self._specs)}")
        spec = self._specs[camera]
        self._mirror.sync()  # rendered now, so taken after not_before
        size = (spec.width, spec.height)
        if size not in self._renderers:
            world = self._mirror.world
            self._renderers[size] = Renderer(world.model, world.geom_entity, *size)
        return self._renderers[size].capture(self._mirror.world.data, camera, spec, segmentation=False)

    def close(self) -> None:
        for renderer in self._renderers.values():
            renderer.close()
        self._renderers.clear()
