"""franky-sim's MuJoCo simulator over one of this project's worlds: the table, furniture and objects built exactly as
the MuJoCo backend builds them (same world file, same seed), with the FR3 where the world mounts its arm, and
franky-sim's libfranka server driving the arm.

franky-sim drives the arm with torques (``qfrc_applied``) and adds the arm's gravity torques itself, as the real
controller does; so the world's own servos on the arm and hand are switched off and the arm's bodies are not
gravity-compensated by MuJoCo, and the physics steps at franky-sim's 1 kHz. This relies on franky-sim 1.0's
``MujocoSimulator`` internals (pinned in the ``franky`` extra).
"""

from __future__ import annotations

import mujoco
import numpy as np
from franky_sim.mujoco_simulator import FrankaMujocoRobot, MujocoSimulator

from roboscript.robots import ROBOT_PREFIX, get_robot
from roboscript.robots.franka_hand import FINGER_STROKE
from roboscript.sim.world import SimWorld, build_world
from roboscript.sim.world_file import WorldSpec

FRANKY_TIMESTEP = 0.001  # franky-sim steps the physics once a libfranka cycle


class WorldSimulator(MujocoSimulator):
    """franky-sim over ``world``; :meth:`add_robot` registers the world's FR3 (no scene XML is built)."""

    def __init__(self, world: WorldSpec):
        super().__init__(enable_visualization=False)
        self.world_spec = world
        self.sim_world: SimWorld | None = None

    def add_robot(self, initial_q=None, **_ignored) -> FrankaMujocoRobot:
        home = get_robot("fr3").home if initial_q is None else initial_q
        robot = FrankaMujocoRobot(initial_q=tuple(home), initial_hand_width=2 * FINGER_STROKE)
        self._robots.append(robot)
        return robot

    def _start(self) -> None:
        self.sim_world = build_world(self.world_spec, "fr3")
        model, data = self.sim_world.model, self.sim_world.data
        model.opt.timestep = FRANKY_TIMESTEP
        for actuator in range(model.nu):  # franky-sim's torques drive the arm and the hand
            if model.actuator(actuator).name.startswith(ROBOT_PREFIX):
                model.actuator_gainprm[actuator, :] = 0.0
                model.actuator_biasprm[actuator, :] = 0.0
        for body in self.sim_world.robot.body_ids:
            model.body_gravcomp[body] = 0.0  # franky-sim adds the arm's gravity torques itself
        self._mj_model, self._mj_data = model, data
        for robot in self._robots:
            robot._attach_to_scene(model, data, ROBOT_PREFIX)
            for address, q in zip(robot._qpos_addrs, robot.initial_q, strict=True):
                data.qpos[address] = q
            for address in robot._finger_qpos_addrs:
                data.qpos[address] = robot._initial_hand_width / 2
        data.qvel[:] = 0.0
        data.qfrc_applied[:] = 0.0
        mujoco.mj_forward(model, data)

    def state(self) -> tuple[np.ndarray, np.ndarray]:
        """A copy of the world's joint positions and velocities (what a mirror of it needs to be in step)."""
        return self._mj_data.qpos.copy(), self._mj_data.qvel.copy()
