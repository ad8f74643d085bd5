"""Reflexes for franky-sim, which simulates none: on request, the arm's running motion ends as an FR3's does when
a joint reflex trips (a collision, a torque limit), so that the libfranka side of the driver meets the robot's own
error state and its recovery over the real protocol.

What the arm does, as libfranka's protocol describes it: the motion is answered ``ReflexAborted``, the arm holds
where it is, and the state it sends reports the robot in ``Reflex`` mode with ``joint_reflex`` among its current and
last motion errors, until an automatic error recovery clears them. A request while no motion runs waits for the next
one (franky-sim's pinned release keeps these as private attributes; the names below are its).
"""

from __future__ import annotations

import threading

from franky_sim.franka_robot_protocol import AutomaticErrorRecoveryCommand, MoveStatus, RobotCommand, RobotMode
from franky_sim.franka_robot_server import FrankaRobotServer
from franky_sim.franka_server import BaseCommand
from franky_sim.simulation_server import SimulationServer

JOINT_REFLEX = 6  # the place of joint_reflex in libfranka's 41 error flags
ERROR_FLAGS = 41


class ReflexingRobotServer(FrankaRobotServer):
    """franky-sim's robot server, with :meth:`trip_reflex` (safe from any thread: the control loop acts on it)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._requested = threading.Event()
        self.in_reflex = False
        self._FrankaServer__command_class_map[RobotCommand.kAutomaticErrorRecovery] = _Recovery

    def trip_reflex(self) -> None:
        """Asks for a reflex during the running motion (or the next one)."""
        self._requested.set()

    def _pre_process_commands(self) -> None:
        super()._pre_process_commands()
        motion = self.current_motion_id
        if motion and self._requested.is_set():
            self._requested.clear()
            self.stop_motion(send_preemption_signal=False)
            self.in_reflex = True
            BaseCommand.send_response(self._tcp_socket, RobotCommand.kMove, motion, MoveStatus.kReflexAborted)
            self.reset_current_motion_id()

    @property
    def robot_state(self):
        state = super().robot_state
        if not self.in_reflex:
            return state
        errors = tuple(flag == JOINT_REFLEX for flag in range(ERROR_FLAGS))
        return state.replace(robot_mode=RobotMode.kReflex, current_errors=errors, last_motion_errors=errors)


class _Recovery(AutomaticErrorRecoveryCommand):
    """libfranka's automatic error recovery, clearing a reflex before it answers."""

    def handle(self, server: ReflexingRobotServer) -> None:
        server.in_reflex = False
        super().handle(server)


class ReflexingSimulationServer(SimulationServer):
    """franky-sim's simulation server with :class:`ReflexingRobotServer` for its robots."""

    def init(self) -> None:
        for robot in self.sim.robots:
            server = ReflexingRobotServer(robot, self._remaining_hostname_candidates)
            server.init()
            self.robot_servers.append(server)
        self.sim.start()

    def trip_reflex(self) -> None:
        for server in self.robot_servers:
            server.trip_reflex()
