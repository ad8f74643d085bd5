"""Steps a :class:`SimWorld` with the robot under control: joint trajectory tracking and gripper commands.

Physics runs at 500 Hz; the controller refreshes its set-points every ``control_stride`` physics steps (250 Hz by
default), and MuJoCo's position servos act on every physics step in between. Set-points carry velocity
feed-forward (so the servos' damping does not lag the motion) and inertial feed-forward (``M(q) qdd``), and the
robot is gravity-compensated, so tracking error stays in the millimetres.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from roboscript.errors import InvalidArgumentError
from roboscript.phases import timed
from roboscript.robot_io import ExecutionReport, GripperReport
from roboscript.sim.world import SimWorld
from roboscript.trajectory import JointTrajectory

StepCallback = Callable[["Simulator"], None]


def _as_slice(indices: np.ndarray) -> slice | np.ndarray:
    """A slice for contiguous ascending indices (fast to index with), else the indices themselves."""
    indices = np.asarray(indices)
    if len(indices) and np.all(np.diff(indices) == 1):
        return slice(int(indices[0]), int(indices[-1]) + 1)
    return indices


class Simulator:
    """Owns stepping: everything that advances simulated time goes through here."""

    def __init__(self, world: SimWorld, control_stride: int = 2):
        self.world = world
        self.model, self.data = world.model, world.data
        self.robot = world.robot
        self.control_stride = control_stride
        self._callbacks: list[StepCallback] = []
        self._scratch = mujoco.MjData(self.model)  # for forward kinematics of set-points
        # With sleeping enabled, kinematics only visits bodies marked awake; a fresh MjData has that mark set by
        # its first mj_forward. Nothing ever steps the scratch data, so every tree in it stays awake.
        mujoco.mj_forward(self.model, self._scratch)
        self._qacc = np.zeros(self.model.nv)
        self._mqacc = np.zeros(self.model.nv)
        lo, hi = self.model.actuator_ctrlrange[self.robot.actuators].T
        self._ctrl_lo, self._ctrl_hi = lo, hi
        # Arm elements are contiguous in every model built here; slices index much faster than index arrays.
        self._arm_ctrl = _as_slice(self.robot.actuators)
        self._arm_dof = _as_slice(self.robot.dof)
        self._arm_qpos = _as_slice(self.robot.qpos)
        self.hold(self.joint_positions())

    # --- state ---------------------------------------------------------------------------------------------

    @property
    def time(self) -> float:
        return float(self.data.time)

    def joint_positions(self) -> np.ndarray:
        return self.data.qpos[self.robot.qpos].copy()

    def joint_velocities(self) -> np.ndarray:
        return self.data.qvel[self.robot.dof].copy()

    def tcp_position(self) -> np.ndarray:
        return self.data.site_xpos[self.robot.tcp_site].copy()

    def tcp_rotation(self) -> np.ndarray:
        return self.data.site_xmat[self.robot.tcp_site].reshape(3, 3).copy()

    def tcp_position_at(self, q: np.ndarray) -> np.ndarray:
        """Forward kinematics of the TCP at arm configuration ``q`` (the rest of the world as it is now)."""
        self._scratch.qpos[:] = self.data.qpos
        self._scratch.qpos[self.robot.qpos] = q
        mujoco.mj_kinematics(self.model, self._scratch)
        return self._scratch.site_xpos[self.robot.tcp_site].copy()

    def gripper_width(self) -> float:
        """Distance between the fingers along the TCP's closing (y) axis, less the description's offset."""
        a, b = (self.data.xpos[i] for i in self.robot.finger_bodies)
        closing_axis = self.tcp_rotation()[:, 1]
        return float(abs(np.dot(a - b, closing_axis)) - self.robot.description.gripper.width_offset)

    @property
    def sleeping_enabled(self) -> bool:
        """Whether bodies at rest may sleep (skip collision and constraint work until touched); on by default."""
        return bool(self.model.opt.enableflags & mujoco.mjtEnableBit.mjENBL_SLEEP)

    @sleeping_enabled.setter
    def sleeping_enabled(self, enabled: bool) -> None:
        flag = int(mujoco.mjtEnableBit.mjENBL_SLEEP)
        self.model.opt.enableflags = (
            (self.model.opt.enableflags | flag) if enabled else (self.model.opt.enableflags & ~flag)
        )

    # --- callbacks -----------------------------------------------------------------------------------------

    def add_step_callback(self, callback: StepCallback) -> None:
        """``callback(simulator)`` runs after every control tick (for recorders and monitors)."""
        self._callbacks.append(callback)

    def remove_step_callback(self, callback: StepCallback) -> None:
        self._callbacks.remove(callback)

    # --- control -------------------------------------------------------------------------------------------

    def hold(self, q: np.ndarray) -> None:
        """Makes ``q`` the arm's set-point, at rest."""
        q = np.asarray(q, dtype=float)
        self._apply(self._servo_ctrl(q, np.zeros_like(q)), np.zeros_like(q))

    def _servo_ctrl(self, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        """Servo commands for set-points ``q``, ``qd`` (one row or many).

        Position servo force = kp (ctrl - q) - kv qdot; ctrl = q* + kv/kp qd* makes it kp e + kv de/dt.
        """
        r = self.robot
        return np.clip(q + (r.kv / r.kp) * qd, self._ctrl_lo, self._ctrl_hi)

    def _apply(self, ctrl: np.ndarray, qdd: np.ndarray) -> None:
        """Writes servo commands and the inertial feed-forward ``M(q) qdd`` for the next tick."""
        self.data.ctrl[self._arm_ctrl] = ctrl
        self._qacc[self._arm_dof] = qdd
        mujoco.mj_mulM(self.model, self.data, self._mqacc, self._qacc)
        self.data.qfrc_applied[self._arm_dof] = self._mqacc[self._arm_dof]

    def _tick(self) -> None:
        mujoco.mj_step(self.model, self.data, nstep=self.control_stride)
        for callback in self._callbacks:
            callback(self)

    @timed("physics")
    def step(self, duration: float) -> None:
        """Advances ``duration`` seconds holding the current set-points."""
        n = round(duration / (self.model.opt.timestep * self.control_stride))
        for _ in range(n):
            self._tick()

    @timed("physics")
    def execute(
        self,
        trajectory: JointTrajectory,
        settle: float = 0.3,
        monitor_every: int = 5,
        max_start_deviation: float = 0.05,
    ) -> ExecutionReport:
        """Tracks ``trajectory`` from the current time, then holds its end for up to ``settle`` seconds.

        The trajectory must start within ``max_start_deviation`` radians of the arm's configuration.

        Set-points for every control tick are computed up front, so the loop does little besides stepping.
        Joint error is measured on every tick; TCP error (actual TCP against forward kinematics of the set-point)
        on every ``monitor_every``-th tick, after the run.
        """
        r = self.robot
        if trajectory.dof != len(r.qpos):
            raise InvalidArgumentError(
                f"trajectory has {trajectory.dof} joints, the {r.description.name} arm has {len(r.qpos)}"
            )
        deviation = float(np.max(np.abs(trajectory.positions[0] - self.joint_positions())))
        if deviation > max_start_deviation:
            raise InvalidArgumentError(
                f"trajectory starts {deviation:.3f} rad away from the current configuration; it must start at "
                f"the robot's joint positions {np.round(self.joint_positions(), 4).tolist()}"
            )
        bad = np.any(
            (trajectory.positions < r.joint_lower - 1e-6) | (trajectory.positions > r.joint_upper + 1e-6),
            axis=1,
        )
        if np.any(bad):
            i = int(np.argmax(bad))
            raise InvalidArgumentError(
                f"trajectory point {i} (t={trajectory.times[i]:.3f} s) leaves the joint limits: "
                f"{np.round(trajectory.positions[i], 4).tolist()} not within {np.round(r.joint_lower, 4).tolist()}"
                f" .. {np.round(r.joint_upper, 4).tolist()}"
            )
        tick = self.model.opt.timestep * self.control_stride
        n = max(1, int(np.ceil(trajectory.duration / tick - 1e-9)))
        q_set, qd_set, qdd_set = trajectory.sample_many(np.arange(1, n + 1) * tick)
        ctrl = self._servo_ctrl(q_set, qd_set)
        actual_q = np.empty_like(q_set)
        monitored = np.arange(monitor_every - 1, n, monitor_every)
        actual_tcp = np.empty((len(monitored), 3))
        start, j = self.time, 0
        for k in range(n):
            self._apply(ctrl[k], qdd_set[k])
            self._tick()
            actual_q[k] = self.data.qpos[self._arm_qpos]
            if j < len(monitored) and monitored[j] == k:
                actual_tcp[j] = self.data.site_xpos[r.tcp_site]
                j += 1
        final = trajectory.positions[-1]
        self.hold(final)
        waited = 0.0
        while waited < settle and np.max(np.abs(self.joint_velocities())) > 0.01:
            self._tick()
            waited += tick
        tcp_errors = [np.linalg.norm(actual_tcp[i] - self.tcp_position_at(q_set[k])) for i, k in enumerate(monitored)]
        final_tcp = float(np.linalg.norm(self.tcp_position() - self.tcp_position_at(final)))
        return ExecutionReport(
            duration=self.time - start,
            max_joint_error=float(np.max(np.abs(actual_q - q_set))),
            max_tcp_error=max([final_tcp, *tcp_errors]),
            final_joint_error=float(np.max(np.abs(self.joint_positions() - final))),
            final_tcp_error=final_tcp,
        )

    @timed("physics")
    def set_gripper(self, closed: float, timeout: float = 1.5) -> GripperReport:
        """Commands the gripper (0 open .. 1 closed) and steps until the fingers stop or ``timeout`` passes."""
        if not 0.0 <= closed <= 1.0:
            raise InvalidArgumentError(f"gripper command must be within 0 (open) and 1 (closed), got {closed}")
        g = self.robot.description.gripper
        self.data.ctrl[self.robot.gripper_actuator] = g.open_ctrl + closed * (g.closed_ctrl - g.open_ctrl)
        start = self.time
        tick = self.model.opt.timestep * self.control_stride
        widths = [self.gripper_width()]
        still = 0
        while self.time - start < timeout:
            self._tick()
            widths.append(self.gripper_width())
            still = still + 1 if abs(widths[-1] - widths[-2]) < 2e-5 else 0
            if still >= int(0.05 / tick) and self.time - start > 0.1:
                break
        width = widths[-1]
        target_width = g.max_width * (1.0 - closed)
        return GripperReport(width, closed, blocked=width > target_width + 0.004, duration=self.time - start)

    @timed("physics")
    def settle(self, max_duration: float = 1.0, linear_tol: float = 0.005, angular_tol: float = 0.05) -> float:
        """Steps until every free object is at rest (speeds under the tolerances), at most ``max_duration``.

        Returns the simulated time it took; ``max_duration`` if something was still moving.
        """
        start = self.time
        while self.time - start < max_duration:
            self._tick()
            if self.objects_at_rest(linear_tol, angular_tol):
                return self.time - start
        return max_duration

    def objects_at_rest(self, linear_tol: float = 0.005, angular_tol: float = 0.05) -> bool:
        speeds = self.object_speeds()
        return bool(np.all(speeds[:, 0] < linear_tol) and np.all(speeds[:, 1] < angular_tol)) if len(speeds) else True

    def object_speeds(self) -> np.ndarray:
        """(linear m/s, angular rad/s) of every free object, in world order."""
        out = []
        for e in self.world.entities:
            if e.kind == "object":
                joint = self.model.body_jntadr[e.bodies[0]]
                dof = self.model.jnt_dofadr[joint]
                v = self.data.qvel[dof : dof + 6]
                out.append((np.linalg.norm(v[:3]), np.linalg.norm(v[3:])))
        return np.array(out).reshape(-1, 2)
