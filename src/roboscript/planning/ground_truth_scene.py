"""Planning against ground truth: a planning scene with the simulated world's exact geometry, kept in step with the
simulation's state (the ``gt`` and ``gt-scene`` perception modes, and tests of the planner)."""

from __future__ import annotations

import copy

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.motion import MotionPlanner
from roboscript.planning.scene import PlanningScene
from roboscript.sim.world import SimWorld


def ground_truth_scene(world: SimWorld, padding: float = 0.005) -> PlanningScene:
    """A scene with the world's exact geometry, in the world's current state."""
    model = copy.copy(world.model)
    labels = [model.body(b).name for b in range(model.nbody)]
    for entity in sorted(world.entities, key=lambda e: e.kind == "part"):  # parts override their furniture
        if entity.kind == "robot":
            continue
        for body in entity.bodies:
            labels[body] = entity.name
    objects = {e.name: e.bodies[0] for e in world.entities if e.kind == "object"}
    scene = PlanningScene(model, world.robot, labels, objects, padding)
    scene.update(world.data.qpos)
    return scene


def ground_truth_motion(backend: MujocoBackend, padding: float = 0.005, **kwargs) -> MotionPlanner:
    """A motion planner whose scene is the simulated world's exact geometry, its state read off the simulation;
    ``kwargs`` go to :class:`MotionPlanner`."""
    world = backend.sim_world
    scene = ground_truth_scene(world, padding=padding)
    kinematics = ArmKinematics(world.robot.description, backend.base_pose())
    return MotionPlanner(backend, scene, kinematics, lambda: world.data.qpos.copy(), **kwargs)
