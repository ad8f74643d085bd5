"""Reflexes for franky-sim, which simulates none: on request, the arm's running motion ends as an FR3's does when
a joint reflex trips (a collision, a torque limit), so that the libfranka side of the driver meets the robot's own
error state and its recovery over the real protocol.

What the arm does, as libfranka's protocol describes it: the motion is answered ``ReflexAborted``, the arm holds
where it is, and the state it sends reports the robot in ``Reflex`` mode with ``joint_reflex`` among its errors and
as the reflex's reason (the state's fields on the wire), until an automatic error recovery clears them. A request
while no motion runs waits for the next one, and trips once libfranka commands that motion: a reflex in the first
millisecond, before libfranka has seen its motion start, ends the start itself, and libfranka names no reason then
(what a loaded machine made of the first version). The recovery sends its clean state before it answers, so that
libfranka's next read of the state shows the errors gone (franky-sim's pinned release keeps these as private
attributes; the names below are its).
"""

from __future__ import annotations

import threading

from franky_sim.franka_robot_protocol import AutomaticErrorRecoveryCommand, MoveStatus, RobotCommand, RobotMode
from franky_sim.franka_robot_server import FrankaRobotServer
from franky_sim.franka_server import BaseCommand
from franky_sim.simulation_server import SimulationServer

JOINT_REFLEX = 6  # the place of joint_reflex in libfranka's 41 error flags
ERROR_FLAGS = 41
STATES_BEFORE_ANSWER = 3  # states (1 ms each) that show the reflex before the motion is answered


class ReflexingRobotServer(FrankaRobotServer):
    """franky-sim's robot server, with :meth:`trip_reflex` (safe from any thread: the control loop acts on it)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._requested = threading.Event()
        self.in_reflex = False
        self._aborting, self._ticks = 0, 0  # the motion a reflex ended, answered after a few states
        self._commanded = 0  # the motion libfranka has sent commands for
        self._FrankaServer__command_class_map[RobotCommand.kAutomaticErrorRecovery] = _Recovery

    def trip_reflex(self) -> None:
        """Asks for a reflex during the running motion (or the next one)."""
        self._requested.set()

    def _pre_process_commands(self) -> None:
        super()._pre_process_commands()
        motion = self.current_motion_id
        if motion and motion == self._commanded and self._requested.is_set() and not self.in_reflex:
            self._requested.clear()
            self.stop_motion(send_preemption_signal=False)
            self.in_reflex, self._aborting, self._ticks = True, motion, STATES_BEFORE_ANSWER
        elif self.in_reflex and self._aborting:
            # libfranka names the errors from the last state it had when the answer came: states first
            self._ticks -= 1
            if self._ticks <= 0:
                BaseCommand.send_response(
                    self._tcp_socket, RobotCommand.kMove, self._aborting, MoveStatus.kReflexAborted
                )
                self._aborting = 0
                self.reset_current_motion_id()

    def _handle_udp_command(self, command_data: bytes) -> None:
        if self.current_motion_id and not self.in_reflex:
            self._commanded = self.current_motion_id
        super()._handle_udp_command(command_data)

    @property
    def robot_state(self):
        state = super().robot_state
        if not self.in_reflex:
            return state
        errors = tuple(flag == JOINT_REFLEX for flag in range(ERROR_FLAGS))
        return state.replace(robot_mode=RobotMode.kReflex, errors=errors, reflex_reason=errors)  # as the wire has them


class _Recovery(AutomaticErrorRecoveryCommand):
    """libfranka's automatic error recovery, clearing a reflex before it answers."""

    def handle(self, server: ReflexingRobotServer) -> None:
        server.in_reflex = False
        server.send_state()
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
