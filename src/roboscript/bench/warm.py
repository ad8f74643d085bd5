"""Warms the process that trials are forked from, as a side effect of importing this module.

MuJoCo keeps the meshes it has decoded in a process-wide asset cache, and the robots' meshes are most of what
compiling a world costs: about 4 s for the Panda's the first time in a process, a third of a second for a whole
world after. The trial fork server (:func:`roboscript.bench.runner.trial_context`) imports this module, so every
trial forked from it starts with the cache warm.
"""

from __future__ import annotations

from roboscript.geometry import Transform
from roboscript.robots import ROBOTS
from roboscript.robots.mujoco_model import RobotModel


def warm_robot_meshes() -> None:
    """Compiles each robot once, alone, so that its meshes are in MuJoCo's asset cache."""
    for description in ROBOTS.values():
        RobotModel(description, Transform.identity())


warm_robot_meshes()
