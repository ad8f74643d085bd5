"""Motion: plans, times and executes arm motions on a backend, keeping the planning scene in step with the world.

This is what the tool API's motion tools call. Every motion starts from the backend's measured configuration.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Mapping, Sequence
from typing import Protocol

import numpy as np

from roboscript.backends.base import Backend
from roboscript.geometry import Transform
from roboscript.load import load_factor
from roboscript.planning.cartesian import CartesianResult, arc_poses, cartesian_path
from roboscript.planning.errors import (
    CartesianPathIncompleteError,
    IKError,
    PathInCollisionError,
    PlannerTimeoutError,
    PlanningError,
    TrackingError,
)
from roboscript.planning.goal_preferences import GoalPreferences
from roboscript.planning.ik import DEFAULT_SEARCH, IKSearch, ik_solutions
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.planner import JointPath, JointPlanner, pose_distance, same_pose, seed_sampling, whole_turns
from roboscript.planning.scene import PlanningScene
from roboscript.planning.timing import time_parameterize
from roboscript.planning.transfer import plan_transfer, upright
from roboscript.robot_io import ExecutionReport

PLANNING_ATTEMPTS = 3  # tries of a planner that runs out of time, each with twice the time of the one before
# While an object is held, motions are timed at this fraction of the arm's limits (at most the free speed): at
# half the limits a planned transfer swept a 0.27 kg banana, pinched across its 3.6 cm body, at 1.4 m/s and up to
# 6.7 m/s^2, and it crept out of the pads and fell. MoveIt's configurations scale far lower still by default.
CARRY_SPEED_SCALE = 0.25


class SceneSource(Protocol):
    """A planning scene that is rebuilt from observations (see :mod:`roboscript.planning.perceived_scene`)."""

    def current(self) -> PlanningScene: ...

    def state(self) -> np.ndarray: ...

    def mark_stale(self, moved: Mapping[str, tuple[np.ndarray, np.ndarray]] | None = None) -> None: ...


class MotionPlanner:
    """Joint-space, pose and Cartesian motions for one arm, executed on a backend with tracking monitoring.

    The scene is either fixed (the simulator's geometry, kept in step by ``world_state``) or comes from a
    :class:`SceneSource`, asked for the scene at every use: when it builds a new one, the contacts allowed in the
    old one and what the gripper holds are carried over by name.
    """

    def __init__(
        self,
        backend: Backend,
        scene: PlanningScene | None,
        kinematics: ArmKinematics,
        world_state: Callable[[], np.ndarray],
        speed_scale: float = 0.5,
        carry_speed_scale: float = CARRY_SPEED_SCALE,
        tracking_tolerance: float = 0.02,
        seed: int | None = None,
        scene_source: SceneSource | None = None,
    ):
        """``seed`` seeds the sampling planners, for repeatable runs (see :func:`seed_sampling`)."""
        if seed is not None:
            seed_sampling(seed)
        self.backend = backend
        if scene is None and scene_source is None:
            raise ValueError("a motion planner needs a planning scene or a source of one")
        self._scene = scene
        self.kinematics = kinematics
        self._planner = None
        if scene is not None:
            self._take(scene)
        self._world_state = world_state
        self.scene_source = scene_source
        self.speed_scale = speed_scale
        self.carry_speed_scale = carry_speed_scale
        self.tracking_tolerance = tracking_tolerance
        self.default_planner = "RRTConnect"
        self.planning_timeout = 2.0
        self.preferences = GoalPreferences()  # configurations chosen for poses ahead of the motions to them

    @property
    def scene(self) -> PlanningScene:
        """The planning scene, rebuilt first if its source has seen the world change."""
        if self.scene_source is not None:
            fresh = self.scene_source.current()
            if self._scene is None:
                self._take(fresh)
            elif fresh is not self._scene:
                self._adopt(fresh)
        return self._scene

    def _take(self, scene: PlanningScene) -> None:
        """Plans in ``scene`` from now on, kept inside the backend's workspace box where it has one."""
        box = self.backend.workspace_box()
        if box is not None:
            scene.keep_inside(*box)
        self._scene, self._planner = scene, JointPlanner(scene)

    @property
    def planner(self) -> JointPlanner:
        """The joint-space planner of the current scene."""
        self.scene  # noqa: B018 (brings the scene, and with it the planner, up to date)
        return self._planner

    def _adopt(self, fresh: PlanningScene) -> None:
        old = self._scene
        held = set(old.attached)
        missing = [name for name in held if name not in fresh.object_bodies]
        if missing:
            raise RuntimeError(
                f"the rebuilt planning scene lacks {', '.join(missing)}, which the gripper holds; objects in it: "
                f"{', '.join(sorted(fresh.object_bodies)) or 'none'}"
            )
        # Contacts of a held object are worked out again when it is attached in the new scene: those it had when
        # grasped are allowed only until it has left them, which a copied pair would not be.
        for a, b in old.allowed_names():
            if a not in held and b not in held and fresh.has(a) and fresh.has(b):
                fresh.allow(a, b)
        fresh.update(self._world_state())
        q = self.backend.joint_positions()
        for name in old.attached:
            fresh.attach(name, q)
        for a, b in old.leaving_names():  # measured anew in the new scene, where the surfaces may differ a little
            if fresh.has(a) and fresh.has(b):
                fresh.allow_leaving(a, b, q)
        self._take(fresh)

    def world_changed(self, moved: Mapping[str, tuple[np.ndarray, np.ndarray]] | None = None) -> None:
        """Something was let go or moved: a scene built from observations is rebuilt before it is next used.
        ``moved``: furniture parts the hand moved (a drawer pushed shut, with its handle), each with where the TCP
        took hold of it and where it let go: what was seen of them before moved on their joints with it."""
        if self.scene_source is not None:
            self.scene_source.mark_stale(moved)

    # --- planning ------------------------------------------------------------------------------------------

    def sync(self) -> np.ndarray:
        """Takes the world's present state into the scene; returns the arm's configuration. Where the scene is the
        simulator's own, so is where each held object sits in the hand.

        A servoed joint resting at a limit can read a hair beyond it; such readings are taken as at the limit.
        """
        self.scene.update(self._world_state(), held_from_state=self.scene_source is None)
        q = self.backend.joint_positions()
        return np.clip(q, self.scene.joint_lower, self.scene.joint_upper)

    def plan_to_joints(self, goal: np.ndarray, planner: str | None = None, timeout: float | None = None) -> JointPath:
        return self.plan(self.sync(), [goal], planner, timeout)

    def plan(
        self, start: np.ndarray, goals: list[np.ndarray], planner: str | None = None, timeout: float | None = None
    ) -> JointPath:
        """A path from ``start`` to the first of ``goals``. A planner that runs out of time tries again with
        twice the time, up to :data:`PLANNING_ATTEMPTS` runs, taking the next goal where there are several (another
        IK branch of the same pose), as MoveIt's planning attempts do: a path that exists is then found on a busy
        machine too (``JointPath.attempts`` says how many runs it took). A run whose every path failed the dense
        validation (a narrow passage the planner's coarser checks slipped through) is retried the same way. While
        the gripper holds something, the path is a transfer (:mod:`roboscript.planning.transfer`) where one can be
        found; the path keeps what the gripper holds upright (:func:`~roboscript.planning.transfer.upright`) on
        every run but the last. Each run's time is scaled by the machine's load
        (:func:`~roboscript.load.load_factor`), as every wall-clock budget here is."""
        name, budget = planner or self.default_planner, self._budget(timeout)
        transfer = bool(self.scene.attached)  # carried clear of everything where that can be done
        for attempt in range(PLANNING_ATTEMPTS):
            goal, limit = goals[attempt % len(goals)], budget * 2**attempt
            if transfer:
                try:
                    path = plan_transfer(self.planner, self.kinematics, start, goal, name, limit)
                    return dataclasses.replace(path, attempts=attempt + 1)
                except (PlannerTimeoutError, PathInCollisionError):
                    pass
                except PlanningError:  # no room to come clear at one end: an ordinary path, from now on
                    transfer = False
            # An ordinary path, without the transfer's clearance; still upright while something is held, but for
            # the last run: a path that tips the hand beats none.
            upright_here = self.scene.attached and attempt < PLANNING_ATTEMPTS - 1
            constraint = upright(self.kinematics, start, goal) if upright_here else None
            try:
                path = self.planner.plan(start, goal, name, limit, constraint=constraint)
                return dataclasses.replace(path, attempts=attempt + 1)
            except (PlannerTimeoutError, PathInCollisionError) as exc:
                last = exc
        raise last

    def connects(self, start: np.ndarray, goal: np.ndarray, timeout: float | None = None) -> bool:
        """Whether one planner run finds a collision-free path from ``start`` to ``goal`` within ``timeout``
        (default: the planning timeout; scaled by the load, as :meth:`plan`'s): a screen for goals that IK reaches
        but a path cannot (a configuration walled in by the table, or reached only through a passage too narrow for
        the dense validation), not a verdict, since a busy machine may need the retries of :meth:`plan`. The
        screen asks for no upright path while the gripper holds something (:meth:`plan` does): one run of a planner
        so constrained often misses the narrow way into a drawer, and the place pose screened then rose 5 cm, from
        where a UR5e's open fingers kept the cup. Contacts the arm starts in may be left, as the motion's will."""
        try:
            with self.scene.leaving_where(start):
                self.planner.plan(start, goal, self.default_planner, self._budget(timeout))
        except (PlannerTimeoutError, PathInCollisionError):
            return False
        return True

    def _budget(self, timeout: float | None) -> float:
        """A planner run's seconds: ``timeout`` (default: the planning timeout) as long as it takes on a busy
        machine."""
        return (timeout or self.planning_timeout) * load_factor()

    def ik(
        self, pose: Transform, reference: np.ndarray | None = None, search: IKSearch = DEFAULT_SEARCH
    ) -> np.ndarray:
        """A collision-free configuration for the TCP at ``pose``, nearest ``reference`` (default: current).

        A smaller ``search`` makes a quick screen of many candidate poses; see
        :func:`~roboscript.planning.ik.ik_solutions`."""
        reference = self.backend.joint_positions() if reference is None else reference
        return ik_solutions(self.kinematics, pose, reference, self.scene, search)[0]

    def ik_choices(
        self, pose: Transform, reference: np.ndarray, search: IKSearch = DEFAULT_SEARCH
    ) -> list[np.ndarray]:
        """Several collision-free configurations for the TCP at ``pose`` (IK branches), nearest ``reference``
        first; see :func:`ik_solutions`."""
        return ik_solutions(self.kinematics, pose, reference, self.scene, search)

    def move_to_any(self, goals: Sequence[np.ndarray], planner: str | None = None) -> int:
        """Plans to the first of ``goals`` (other IK branches of one pose) that a path reaches, trying the next
        where the planner runs out of time, executes it, and returns the index of the goal reached."""
        path = self.plan(self.sync(), list(goals), planner, None)
        self.execute(path)
        return int(np.argmin([pose_distance(path.goal, g) for g in goals]))

    def plan_to_pose(self, pose: Transform, planner: str | None = None, timeout: float | None = None) -> JointPath:
        """A planned path to ``pose``: to the configuration preferred for it, if one is (tried twice), then to
        other IK branches. The configurations preferred for other poses seed the IK (the program's own pose above
        a chosen place pose, at the edge of the reach, is found from the place's configuration)."""
        start = self.sync()
        preferred = self.preferences.preferred_for(pose, self.scene.is_valid)
        seeds = self.preferences.seeds()
        try:
            goals = ik_solutions(
                self.kinematics, pose, start, self.scene, IKSearch(solutions=PLANNING_ATTEMPTS), seeds=seeds
            )
        except IKError:
            if preferred is None:
                raise
            goals = []
        if preferred is not None:
            goals = [preferred, preferred, *goals]
        return self.plan(start, goals, planner, timeout)

    def cartesian(
        self, poses: Sequence[Transform], eef_step: float = 0.005, start: np.ndarray | None = None
    ) -> CartesianResult:
        """Straight TCP lines through ``poses`` from ``start`` (default: the present configuration); see
        :func:`cartesian_path`."""
        start = self.sync() if start is None else np.asarray(start, dtype=float)
        return cartesian_path(self.kinematics, self.scene, start, list(poses), eef_step)

    # --- execution -----------------------------------------------------------------------------------------

    def execute(self, waypoints: np.ndarray | JointPath) -> ExecutionReport:
        """Times the path within the arm's limits (at ``speed_scale``, or ``carry_speed_scale`` while an object is
        held), runs it, and checks it was followed."""
        points = waypoints.waypoints if isinstance(waypoints, JointPath) else np.asarray(waypoints, dtype=float)
        robot = self.backend.robot
        scale = min(self.speed_scale, self.carry_speed_scale) if self.scene.attached else self.speed_scale
        trajectory = time_parameterize(points, robot.max_velocity, robot.max_acceleration, scale)
        report = self.backend.execute_trajectory(trajectory)
        if report.max_tcp_error > self.tracking_tolerance:
            raise TrackingError(report.max_tcp_error, self.tracking_tolerance)
        return report

    def move_to_joints(self, goal: np.ndarray, planner: str | None = None) -> ExecutionReport:
        return self.execute(self.plan_to_joints(goal, planner))

    def move_to_pose(self, pose: Transform, planner: str | None = None) -> ExecutionReport:
        """A straight line when it is feasible in full and ends in the configuration preferred for ``pose`` (if
        one is), else a planned collision-free motion."""
        line = self.cartesian([pose])
        preferred = self.preferences.preferred_for(pose, self.scene.is_valid)
        if line.fraction >= 1.0 and (preferred is None or same_pose(line.waypoints[-1], preferred, 0.2)):
            path = line.waypoints
        else:
            way_in = self._way_in(pose, preferred)
            if way_in is not None:
                try:
                    self.execute(self.plan(self.sync(), [way_in[0]], planner, None))
                except (PlannerTimeoutError, PathInCollisionError):
                    way_in = None  # no path to its mouth either: planned to the pose itself, below
            if way_in is not None:
                self.preferences.preferred_for(pose, self.scene.is_valid, consume=True)
                here = self.from_here(way_in)
                # Reached its mouth a whole turn about a joint off, the line in would pass a limit: planned in.
                return self.execute(here if here is not None else self.plan_to_joints(way_in[-1], planner))
            path = self.plan_to_pose(pose, planner)
        self.preferences.preferred_for(pose, self.scene.is_valid, consume=True)
        return self.execute(path)

    def _way_in(self, pose: Transform, goal: np.ndarray | None) -> np.ndarray | None:
        """The straight line into ``pose`` ending at ``goal`` (the configuration preferred for it), along the way
        out registered with it (:meth:`GoalPreferences.prefer`), as joint waypoints from its mouth; None where there
        is none or the line is blocked."""
        way_out = self.preferences.way_out(pose)
        if goal is None or way_out is None:
            return None
        mouth = Transform(pose.position + way_out, pose.quaternion)
        line = self.cartesian([mouth], start=goal)
        return line.waypoints[::-1].copy() if line.fraction >= 1.0 and len(line.waypoints) > 1 else None

    def from_here(self, line: np.ndarray) -> np.ndarray | None:
        """``line`` starting from the present configuration, which the motion to its start reached (perhaps a
        whole turn about a joint away: planner.py); None where it then passes a joint limit."""
        q = self.sync()
        line = line + whole_turns(line[0], q)
        line[0] = q
        within = self.scene.within_limits(line.min(axis=0)) and self.scene.within_limits(line.max(axis=0))
        return line if within else None

    def follow(self, poses: Sequence[Transform], min_fraction: float = 1.0) -> ExecutionReport:
        """Executes a Cartesian path through ``poses``; raises if less than ``min_fraction`` is achievable."""
        result = self.cartesian(poses)
        if result.fraction < min_fraction - 1e-9:
            raise CartesianPathIncompleteError(result.fraction, result.reason)
        return self.execute(result.waypoints)

    def move_in_direction(
        self, direction: np.ndarray, distance: float, min_fraction: float = 1.0, plan_if_blocked: bool = False
    ) -> ExecutionReport:
        """Moves the TCP in a straight line by ``distance`` metres along ``direction``, orientation kept.

        With ``plan_if_blocked``, a line that cannot be followed (a singularity, a joint limit, or the IK branch
        swinging a link into something) gives way to a planned collision-free motion to the same end pose.
        """
        direction = np.asarray(direction, dtype=float)
        norm = float(np.linalg.norm(direction))
        if direction.shape != (3,) or norm < 1e-9:
            raise ValueError(f"direction must be a non-zero 3-vector, got {direction.tolist()}")
        current = self.backend.tcp_pose()
        target = Transform(current.position + direction / norm * distance, current.quaternion)
        try:
            return self.follow([target], min_fraction)
        except CartesianPathIncompleteError:
            if not plan_if_blocked:
                raise
            return self.execute(self.plan_to_pose(target))

    def retreat(self, direction: np.ndarray, distance: float, least: float = 0.01) -> float:
        """Moves the TCP straight along ``direction`` by up to ``distance`` metres, as far as a straight line goes
        (a post-grasp or post-place retreat, as MoveIt's pick and place pipelines make); nothing where less than
        ``least`` is free. Returns the distance moved."""
        direction = np.asarray(direction, dtype=float) / float(np.linalg.norm(direction))
        current = self.backend.tcp_pose()
        line = self.cartesian([Transform(current.position + direction * distance, current.quaternion)])
        if line.fraction * distance < least or len(line.waypoints) < 2:
            return 0.0
        self.execute(line.waypoints)
        return line.fraction * distance

    def hold_here(self) -> np.ndarray:
        """Holds the arm where it stands: after a motion blocked short of its end the controller still drives
        toward that end (against a drawer's stop). Returns the configuration."""
        q = self.sync()
        robot = self.backend.robot
        self.backend.execute_trajectory(time_parameterize(np.array([q, q]), robot.max_velocity, robot.max_acceleration))
        return q

    def reach_along(self, q: np.ndarray, direction: np.ndarray, distance: float) -> float:
        """How far, up to ``distance``, the TCP of the arm at ``q`` could move straight along ``direction`` (the
        hand kept as it is) within the arm's reach: IK and continuity only, collisions not checked (a question
        about a configuration the arm is not in yet)."""
        direction = np.asarray(direction, dtype=float) / float(np.linalg.norm(direction))
        start = self.kinematics.fk(q)
        end = Transform(start.position + direction * distance, start.quaternion)
        return cartesian_path(self.kinematics, None, q, [end]).fraction * distance

    def arc(self, axis: np.ndarray, pivot: np.ndarray, angle: float, n: int = 20, min_fraction: float = 1.0):
        """Turns the TCP about a revolute joint (a door's hinge) by ``angle`` radians."""
        return self.follow(arc_poses(self.backend.tcp_pose(), axis, pivot, n, angle), min_fraction)

    # --- held objects --------------------------------------------------------------------------------------

    def attach(self, name: str) -> None:
        self.sync()
        self.scene.attach(name, self.backend.joint_positions())

    def detach(self, name: str) -> None:
        self.scene.detach(name)
        self.preferences.clear()  # chosen for placing what was held
        self.sync()

