"""The tool API: the functions a generated program calls (DESIGN.md §3), on a backend, perception and planner.

Every tool checks its arguments first and raises an error that names what was wrong and what would be valid; a
failed tool leaves the world as it was (nothing moves before a motion has been planned in full).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from roboscript.api.placement import (
    MARGIN,
    Footprint,
    PlacementError,
    PlacementSpot,
    ReceptacleFullError,
    fits,
    spot_at,
    spots_in_receptacle,
)
from roboscript.api.pose import Pose, _real
from roboscript.api.signature import tool
from roboscript.backends.base import Backend
from roboscript.geometry import Box3D, Transform, quat_from_yaw, quat_to_matrix
from roboscript.perception.base import TABLE, Perception, Receptacle, UnknownObjectError
from roboscript.perception.grasp_detection import (
    WIDTH_MARGIN,
    GraspPreferences,
    GripperGeometry,
    detect_grasps,
    score_grasp,
)
from roboscript.perception.grasp_heuristics import GraspError, central_lift_grasps, horizontal_grasps
from roboscript.planning.cartesian import arc_poses, cartesian_path
from roboscript.planning.errors import IKError, PlanningError
from roboscript.planning.motion import MotionPlanner

PRE_GRASP_DISTANCE = 0.1
# A box grasp closes on the faces of the object's footprint, not on a pair of points checked against friction:
# ranked with the contact quality of a middling antipodal pair.
BOX_GRASP_QUALITY = 0.5
WIDE_BRANCH_SEARCH = 4  # the best-ranked grasp candidates whose approach is sought on more IK branches
# Retreats made on the program's behalf before its next motion, unless that motion is one itself: a held object is
# lifted off its support (up), a released one left behind (the hand backs off along its approach axis).
LIFT_AFTER_GRASP = 0.05
RETREAT_AFTER_RELEASE = 0.05
RELEASE_RETREAT_LEAST = 0.02  # a program's own retreat after a release may stop short of its distance, not of this
OWN_RETREAT = 0.5  # cosine (60 deg) above which a program's motion is its own retreat; wider than PREFERENCE_CONE
PULL_CHECK = 0.25  # metres a drawer handle grasp must be able to pull
DRAWER_WALL_MARGIN = 0.025
PLACE_IK_BUDGET = 96  # IK screens per parse_place_pose call (each costs a few milliseconds to ~0.1 s)
PLACE_RAISE_LIMIT = 0.04  # metres a place pose is raised at most when the held object has sunk in the hand
PLACE_RETREAT = 0.08  # metres a place pose should leave the hand room to retreat straight up
# Where things may be put down on the table, from the robot's base: in front of it, clear of it, within reach.
TABLE_REACH = (np.array([0.15, -0.45]), np.array([0.73, 0.45]))
JOINT_TYPES = ("any", "revolute", "prismatic")


class ToolAPI:
    """The tools, bound to one robot. :meth:`namespace` is what a program sees."""

    def __init__(self, backend: Backend, perception: Perception, motion: MotionPlanner, seed: int = 0):
        self.backend = backend
        self.perception = perception
        self.motion = motion
        self.seed = seed
        gripper = backend.robot.gripper
        self.gripper = GripperGeometry(
            max_width=gripper.max_width, hand_lower=gripper.hand_box[0], hand_upper=gripper.hand_box[1]
        )
        self.base_xy = np.asarray(motion.kinematics.mount.position[:2], dtype=float)
        self._held: list[str] = []
        # Names the gripper may touch until it has moved clear of them (what it grasped or just let go of).
        self._touch_allowed: set[str] = set()
        self._link_contacts: set[tuple[str, str]] = set()  # arm links allowed to leave a contact they start in
        # Owed before the next motion: (direction, distance, "lift" after a grasp or "release" after letting go).
        self._pending_retreat: tuple[np.ndarray, float, str] | None = None

    @classmethod
    def for_simulation(cls, backend, seed: int = 0, perception: str = "gt") -> ToolAPI:
        """The tools on a simulated ``backend``, with perception and the planning scene as the mode
        ``perception`` says (see :mod:`roboscript.perception.modes`): ground truth by default."""
        from roboscript.perception.modes import make_perception, parse_mode

        seen = make_perception(perception, backend, seed)
        if parse_mode(perception).observed_scene:
            motion = MotionPlanner.perceived_in_mujoco(backend, seen, seed=seed)
        else:
            motion = MotionPlanner.for_mujoco(backend, seed=seed)
        return cls(backend, seen, motion, seed)

    # --- the program's view ----------------------------------------------------------------------------------

    TOOL_NAMES = (
        "get_object_name_list",
        "detect_objects",
        "get_object_center_position",
        "get_object_pose",
        "get_3d_bbox",
        "get_object_joint_info",
        "get_plane_normal",
        "parse_central_lift_grasp_pose",
        "parse_horizontal_grasp_pose",
        "parse_adaptive_shape_grasp_pose",
        "open_gripper",
        "close_gripper",
        "get_gripper_pose",
        "move_to_pose",
        "move_in_direction",
        "generate_arc_path_around_joint",
        "follow_path",
        "grasp",
        "parse_place_pose",
        "attach_object",
        "detach_object",
    )

    def namespace(self) -> dict[str, object]:
        """The names a program may use: every tool, ``np`` and ``Pose``."""
        names: dict[str, object] = {name: getattr(self, name) for name in self.TOOL_NAMES}
        names["np"] = np
        names["Pose"] = Pose
        return names

    # --- perception tools ------------------------------------------------------------------------------------

    @tool
    def get_object_name_list(self) -> list[str]:
        """Names of the known objects and furniture parts (``cabinet.drawer_0``, ``cabinet.handle_0``, ...)."""
        return list(self.perception.names())

    @tool
    def detect_objects(self, object_list: Sequence[str] | None = None) -> None:
        """Runs perception for these categories (all if None): looks with the cameras and updates what is known."""
        if object_list is not None:
            if isinstance(object_list, str) or not all(isinstance(n, str) for n in object_list):
                raise TypeError(f"object_list must be a list of names, e.g. ['apple', 'bowl'], got {object_list!r}")
            object_list = list(object_list)
        self.perception.detect(object_list)
        self.motion.world_changed()

    @tool
    def get_object_center_position(self, object_name: str) -> np.ndarray:
        """Centre of the object's 3D box, world frame, metres."""
        return self.perception.box(self._name(object_name)).center

    @tool
    def get_object_pose(self, object_name: str) -> Pose:
        """The object's pose (its frame: for objects the centre of the bottom face)."""
        return Pose.from_transform(self.perception.pose(self._name(object_name)))

    @tool
    def get_3d_bbox(self, object_name: str) -> np.ndarray:
        """``[x_min, y_min, z_min, x_max, y_max, z_max]`` of the object's world-aligned box."""
        return self.perception.box(self._name(object_name)).as_array()

    @tool
    def get_object_joint_info(self, object_name: str, position: Sequence[float], type: str = "any") -> dict:
        """The joint of the object closest to ``position``: ``{"joint_position", "joint_axis", "type"}``."""
        name = self._name(object_name)
        point = _vector(position, "position")
        if type not in JOINT_TYPES:
            raise ValueError(f"type must be one of {', '.join(JOINT_TYPES)}, got {type!r}")
        joints = [j for j in self.perception.joints(name) if type in ("any", j.type)]
        if not joints:
            articulated = [n for n in self.perception.names() if self.perception.joints(n)]
            kind = "" if type == "any" else f"{type} "
            raise ValueError(f"{name!r} has no {kind}joint; articulated objects: {', '.join(articulated) or 'none'}")
        joint = min(joints, key=lambda j: float(np.linalg.norm(j.position - point)))
        return {"joint_position": joint.position.copy(), "joint_axis": joint.axis.copy(), "type": joint.type}

    @tool
    def get_plane_normal(self, object_name: str, position: Sequence[float]) -> np.ndarray:
        """Outward unit normal of the object's planar face closest to ``position``."""
        return self.perception.plane_normal(self._name(object_name), _vector(position, "position"))

    @tool
    def parse_central_lift_grasp_pose(self, object_name: str, description: str = "top") -> Pose:
        """A top-down grasp at the box centre in x, y; z near the top ("top") or at mid height ("center")."""
        name = self._name(object_name)
        candidates = central_lift_grasps(self.perception, name, description, self.gripper.max_width, self.base_xy)
        return Pose.from_transform(self._first_reachable(name, candidates, "central lift"))

    @tool
    def parse_horizontal_grasp_pose(self, object_name: str, approach_direction: Sequence[float] | None = None) -> Pose:
        """A grasp approaching horizontally (handles, upright objects), along ``approach_direction`` if given."""
        name = self._name(object_name)
        approach = None if approach_direction is None else _vector(approach_direction, "approach_direction")
        candidates = horizontal_grasps(self.perception, name, approach, self.gripper.max_width, self.base_xy)
        return Pose.from_transform(self._first_reachable(name, candidates, "horizontal"))

    @tool
    def parse_adaptive_shape_grasp_pose(
        self,
        object_name: str,
        preferred_position: Sequence[float] | None = None,
        preferred_approach_direction: Sequence[float] | None = None,
        preferred_plane_normal: Sequence[float] | None = None,
    ) -> Pose:
        """The best reachable 6-DoF grasp from antipodal sampling over the object's observed points."""
        name = self._name(object_name)
        preferences = GraspPreferences(
            position=None if preferred_position is None else _vector(preferred_position, "preferred_position"),
            approach=None
            if preferred_approach_direction is None
            else _direction(preferred_approach_direction, "preferred_approach_direction"),
            plane_normal=None
            if preferred_plane_normal is None
            else _direction(preferred_plane_normal, "preferred_plane_normal"),
        )
        cloud = self.perception.points(name)
        if len(cloud.points) < 10:
            raise GraspError(
                f"{name!r} is hardly visible to the cameras ({len(cloud.points)} points): no grasp detected"
            )
        detected = detect_grasps(cloud, self.perception.scene_points(), self.gripper, preferences, seed=self.seed)
        # The box grasps that fit the object compete too, ranked by the same score: where sampling finds pairs
        # only off the middle (a banana half hidden from the cameras) or none within reach (an object nearly as
        # wide as the opening), the adaptive grasp is then no worse than the central or horizontal one.
        width = self.gripper.max_width - WIDTH_MARGIN
        ranked = [(c.score, c.pose) for c in detected[:12]] + [
            (score_grasp(pose, width, BOX_GRASP_QUALITY, cloud, preferences), pose)
            for pose in self._box_grasps(name, preferences)
        ]
        candidates = [pose for _, pose in sorted(ranked, key=lambda c: -c[0])]
        if not candidates:
            raise GraspError(
                f"no collision-free antipodal grasp found on {name!r} ({len(cloud.points)} points seen), and it is "
                f"wider than the gripper's {self.gripper.max_width * 100:.1f} cm opening across every side"
            )
        return Pose.from_transform(self._first_reachable(name, candidates, "adaptive"))

    def _box_grasps(self, name: str, preferences: GraspPreferences) -> list[Transform]:
        """The central lift and horizontal grasps that fit ``name``, in the order the preferred approach suggests
        (top-down first unless a horizontal approach is preferred)."""
        kinds = [
            lambda: central_lift_grasps(self.perception, name, "center", self.gripper.max_width, self.base_xy),
            lambda: horizontal_grasps(self.perception, name, None, self.gripper.max_width, self.base_xy),
        ]
        if preferences.approach is not None and abs(float(preferences.approach[2])) < 0.5:
            kinds.reverse()
        out: list[Transform] = []
        for kind in kinds:
            try:
                out += kind()
            except GraspError:
                continue
        return out

    # --- motion tools ----------------------------------------------------------------------------------------

    @tool
    def open_gripper(self) -> None:
        """Opens the gripper fully."""
        self.backend.open_gripper()
        if self._held:  # what was let go stays behind
            self._pending_retreat = (-self.backend.tcp_pose().rotation[:, 2], RETREAT_AFTER_RELEASE, "release")

    @tool
    def close_gripper(self) -> None:
        """Closes the gripper until the fingers stop (on an object, or fully closed)."""
        self.backend.close_gripper()

    @tool
    def get_gripper_pose(self) -> Pose:
        """The present TCP pose (between the fingertips; z is the approach direction)."""
        return Pose.from_transform(self.backend.tcp_pose())

    @tool
    def move_to_pose(self, pose: Pose) -> None:
        """Collision-free motion of the TCP to ``pose``: a straight line when feasible, else a planned path."""
        target = _pose(pose, "pose")
        self._retreat_first(target.position - self.backend.tcp_pose().position)
        self._allow_start_contacts()
        self._allow_touch_near(target.position)
        try:
            self.motion.move_to_pose(target)
        except IKError as exc:
            higher = self._release_height(target, exc)
            if higher is None:
                raise
            print(
                f"[move_to_pose] {', '.join(self._held)} sits lower in the hand than when the pose was made: "
                f"going {higher.position[2] - target.position[2]:.3f} m higher"
            )
            self.motion.move_to_pose(higher)
        self._after_motion()

    def _release_height(self, target: Transform, error: IKError) -> Transform | None:
        """Where the TCP reaches ``target`` but only what it holds collides (an object that turned or slid down
        in the fingers since its place pose was made, now pressed into its support), the same pose raised the
        least that clears it, within :data:`PLACE_RAISE_LIMIT`; else None."""
        held = set(self._held)
        if not held or not error.colliding or error.position_error > 1e-3:
            return None
        if not all(a in held or b in held for a, b in error.colliding):
            return None
        for lift in np.arange(0.01, PLACE_RAISE_LIMIT + 1e-9, 0.01):
            raised = Transform(target.position + np.array([0.0, 0.0, lift]), target.quaternion)
            try:
                self.motion.ik(raised)
            except IKError:
                continue
            return raised
        return None

    @tool
    def move_in_direction(self, axis: Sequence[float], distance: float) -> None:
        """Moves the TCP in a straight line along ``axis`` by ``distance`` metres, keeping its orientation."""
        direction = _direction(axis, "axis")
        distance = _real(distance, "distance")
        if abs(distance) > 1.5:
            raise ValueError(f"distance is in metres and must be within [-1.5, 1.5], got {distance}")
        own = self._retreat_first(direction * distance)
        self._allow_start_contacts()
        if own == "release":
            # Backing off from what was just let go goes as far as reach allows: an opened drawer's handle may
            # stand at the edge of the workspace, and the retreat's purpose (clearing it) is met before its end.
            moved = self.motion.retreat(direction, distance, least=min(RELEASE_RETREAT_LEAST, distance))
            if moved > 0.0:
                if moved < distance - 1e-3:
                    print(f"[move_in_direction] retreated {moved:.3f} m of {distance:.3f} m: the rest is out of reach")
                self._after_motion()
                return
        self.motion.move_in_direction(direction, distance, plan_if_blocked=True)
        self._after_motion()

    @tool
    def generate_arc_path_around_joint(
        self, current_pose: Pose, joint_axis: Sequence[float], joint_position: Sequence[float], n: int, angle: float
    ) -> list[Pose]:
        """``n`` TCP poses turning ``current_pose`` about the joint axis by ``angle`` degrees in all."""
        start = _pose(current_pose, "current_pose")
        axis = _direction(joint_axis, "joint_axis")
        pivot = _vector(joint_position, "joint_position")
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 1 <= n <= 1000:
            raise ValueError(f"n must be a whole number of waypoints in [1, 1000], got {n!r}")
        angle = _real(angle, "angle")
        if abs(angle) > 360:
            raise ValueError(f"angle is in degrees and must be within [-360, 360], got {angle}")
        return [Pose.from_transform(t) for t in arc_poses(start, axis, pivot, int(n), math.radians(angle))]

    @tool
    def follow_path(self, path: Sequence[Pose]) -> None:
        """Executes a list of poses as one Cartesian path."""
        if isinstance(path, Pose) or not isinstance(path, (list, tuple)) or not path:
            raise TypeError(f"path must be a non-empty list of Pose, got {type(path).__name__}")
        targets = [_pose(p, f"path[{i}]") for i, p in enumerate(path)]
        self._retreat_first(targets[0].position - self.backend.tcp_pose().position)
        self._allow_start_contacts()
        self.motion.follow(targets)
        self._after_motion()

    @tool
    def grasp(self, grasp_pose: Pose) -> None:
        """Moves to a pre-grasp pose 0.1 m back along the approach axis, then straight to ``grasp_pose``.

        The gripper is not closed; call ``close_gripper()`` next.
        """
        target = _pose(grasp_pose, "grasp_pose")
        pre = Transform(target.position - PRE_GRASP_DISTANCE * target.rotation[:, 2], target.quaternion)
        # The way to the pre-grasp is planned, not straight: it is never the retreat itself, whatever its direction.
        self._retreat_first(None)
        self._allow_start_contacts()
        # The fingers may touch the object only on the final straight approach, not on the way to its start.
        q = self.motion.sync()
        with _touch(self.motion, self._new_touches(target.position)):
            options = self.motion.straight_approaches(target, PRE_GRASP_DISTANCE, q)
        # Each IK branch with a clear approach line is a goal: where the planner finds none to one branch's
        # pre-grasp (it may be walled in by the table on a 6-joint arm), it tries the next.
        starts = [approach[0] if approach is not None else self.motion.ik(pre, goal) for goal, approach in options]
        goal, approach = options[self.motion.move_to_any(starts)]
        self._allow_touch_near(target.position)
        if approach is not None:
            approach[0] = self.motion.sync()
            self.motion.execute(approach)
        else:
            line = self.motion.cartesian([target])
            # Should the straight approach be blocked after all (the world moved), a planned one is the fallback.
            self.motion.execute(line.waypoints if line.fraction >= 1.0 else self.motion.plan_to_joints(goal))
        self._after_motion()

    @tool
    def parse_place_pose(
        self, object_name: str, receptacle_name: str | None = None, position: Sequence[float] | None = None
    ) -> Pose:
        """A reachable gripper pose that puts the held object into/onto the receptacle, or at ``position``."""
        name = self._name(object_name)
        if (receptacle_name is None) == (position is None):
            raise ValueError(
                "give exactly one of receptacle_name (e.g. 'plate', 'cabinet.drawer_1') or position [x, y, z]"
            )
        if name not in self._held:
            held = ", ".join(self._held) or "nothing"
            raise ValueError(
                f"parse_place_pose needs {name!r} in the gripper (it holds {held}): grasp it, close_gripper() and "
                f"attach_object({name!r}) first"
            )
        others = [o for o in self.perception.objects() if o not in (name, receptacle_name)]
        if position is not None:
            target = _vector(position, "position")
            spots, where = [self._spot_at(name, target, others)], f"at {np.round(target, 3).tolist()}"
        else:
            receptacle = self._receptacle(receptacle_name, name)
            if receptacle_name == TABLE:
                spots = self._spots_aside(name, receptacle, others)
            else:
                spots = self._spots_in(name, receptacle, others)
            if not spots:
                inside = [o for o in others if _within(self.perception.box(o), receptacle)]
                size = self.perception.box(name).size
                raise ReceptacleFullError(
                    f"{receptacle_name!r} has no free spot for {name!r} "
                    f"({size[0] * 100:.0f} x {size[1] * 100:.0f} cm); "
                    f"it holds {', '.join(inside) or 'nothing'}"
                )
            where = f"in {receptacle_name!r}"
        # Spots are where the middle of the object's footprint goes (for a curved banana lying turned, not the
        # middle of its world-aligned box): the hand turns about that.
        footprint_center = self.perception.footprint(name)[0]
        pivot = np.array([footprint_center[0], footprint_center[1], self.perception.box(name).center[2]])
        return Pose.from_transform(self._reachable_place(name, self.backend.tcp_pose(), pivot, spots, where))

    def _spot_at(self, name: str, target: np.ndarray, others: list[str]) -> PlacementSpot:
        """The held object at ``target``, resting on whatever is under it there (the table at least)."""
        size = self.perception.box(name).size
        below = [self.perception.box(o) for o in others]
        table_top = float(self.perception.box(TABLE).upper[2])
        support = max([table_top] + [b.upper[2] for b in below if _overlaps_xy(b, target[:2], size[:2] / 2)])
        return spot_at(target, size, support)

    def _spots_aside(self, name: str, table: Receptacle, others: list[str]) -> list[PlacementSpot]:
        """Spots on the table for putting the held object aside: clear of objects, furniture and whatever the
        cameras see there, near where it was but not on it."""
        box = self.perception.box(name)
        _, yaw, half = self.perception.footprint(name)
        obstacles = [self._footprint(o) for o in others]
        obstacles += [Footprint.of_box(self.perception.box(n)) for n in self.perception.furniture()]
        spots = spots_in_receptacle(table, half, yaw, box.size[2], obstacles, self.base_xy, near_xy=box.center[:2])
        radius = float(np.linalg.norm(half)) + MARGIN
        spots = _clear_of(spots, self.perception.occupied([name]), radius, table.lower[2])
        return [s for s in spots if np.linalg.norm(s.center[:2] - box.center[:2]) > 0.15]

    def _spots_in(self, name: str, receptacle: Receptacle, others: list[str]) -> list[PlacementSpot]:
        """Free spots for the held object in a container or a drawer, clear of what is already in it."""
        _, yaw, half = self.perception.footprint(name)
        inside = [self._footprint(o) for o in others if _within(self.perception.box(o), receptacle)]
        # A drawer's front and walls stand high around a held object that may swing a little.
        wall_margin = DRAWER_WALL_MARGIN if ".drawer_" in receptacle.name else MARGIN
        height = self.perception.box(name).size[2]
        corner = self._fill_corner(receptacle)
        return spots_in_receptacle(receptacle, half, yaw, height, inside, corner, wall_margin=wall_margin)

    @tool
    def attach_object(self, object_name: str) -> None:
        """Makes the planning scene carry ``object_name`` with the gripper (after closing on it)."""
        name = self._name(object_name)
        if name in self._held:
            return
        is_object = name in self.perception.objects()
        if not is_object and "." not in name:
            movable = [n for n in self.perception.furniture() if "." in n]
            raise ValueError(
                f"{name!r} cannot be held: it does not move. Attach what the gripper holds: an object "
                f"({', '.join(self.perception.objects()) or 'none'}) or a drawer or door, or its handle "
                f"({', '.join(movable) or 'none'})"
            )
        self._held.append(name)
        self._touch_allowed.add(name)
        if not is_object:  # a part of furniture (cabinet.drawer_1): it moves on its joint, or with its drawer
            for part in self._part_family(name):  # the gripper may touch it and its handle
                self.motion.scene.allow("gripper", part)
            return
        self.motion.attach(name)
        self.perception.carried(name, self.backend.tcp_pose())
        # Off whatever it rests on, at once if the fingers hold it: where it settles in the hand, and so what a
        # place pose asked for next must allow for, shows only once it hangs free.
        self._pending_retreat = (np.array([0.0, 0.0, 1.0]), LIFT_AFTER_GRASP, "lift")
        if self.backend.gripper_width() < self.gripper.max_width - 0.005:
            self._retreat_first(None)

    @tool
    def detach_object(self, object_name: str) -> None:
        """Returns ``object_name`` to the planning scene's world (after opening the gripper)."""
        name = self._name(object_name)
        if name not in self._held:
            raise ValueError(f"{name!r} is not attached; attached: {', '.join(self._held) or 'nothing'}")
        self._held.remove(name)
        self.perception.released(name, self.backend.tcp_pose())
        if name in self.perception.objects():
            self.motion.detach(name)
            self.motion.scene.allow_leaving("gripper", name, self.motion.sync())
        else:  # a handle let go: the open fingers may back out of it, not sweep through it
            q = self.motion.sync()
            for part in self._part_family(name):
                self.motion.scene.allow("gripper", part, False)
                self.motion.scene.allow_leaving("gripper", part, q)
        self.motion.world_changed()
        self._touch_allowed.add(name)

    # --- internals -------------------------------------------------------------------------------------------

    def _retreat_first(self, motion: np.ndarray | None) -> str | None:
        """Makes the retreat owed since the last grasp or release, unless ``motion`` (the program's next straight
        move, as a displacement of the TCP; None for a planned one) is already one: mostly along the retreat, and
        at least as long. Returns the retreat's kind ("lift" or "release") when ``motion`` is the program's own
        retreat, else None."""
        pending, self._pending_retreat = self._pending_retreat, None
        if pending is None:
            return None
        direction, distance, kind = pending
        length = 0.0 if motion is None else float(np.linalg.norm(motion))
        if length >= distance and float(direction @ motion) / length > OWN_RETREAT:
            return kind
        self._allow_start_contacts()
        self.motion.retreat(direction, distance)
        self._after_motion()
        return None

    def _name(self, name: object) -> str:
        return self.perception.require(name)

    def _part_family(self, name: str) -> list[str]:
        """A part with its handle and the part the handle is on (``cabinet.drawer_1`` <-> ``cabinet.handle_1``)."""
        family = {name}
        for joint in self.perception.joints(name):
            family.add(joint.part)
        prefix, _, part = name.rpartition(".")
        if part.startswith(("drawer_", "door_", "handle_")):
            for other in self.perception.names():
                if other.startswith(prefix + ".") and any(j.part in family for j in self._joints_if_known(other)):
                    family.add(other)
        return sorted(family)

    def _joints_if_known(self, name: str) -> list:
        """The joints of ``name``, or none where perception cannot tell them (a part whose handle was not seen):
        a question about one part should not fail over another."""
        try:
            return self.perception.joints(name)
        except (UnknownObjectError, ValueError):
            return []

    def _holds_things(self, name: str) -> bool:
        """Whether ``name`` is a receptacle, for an error message: False where perception cannot tell."""
        try:
            return self.perception.receptacle(name) is not None
        except (UnknownObjectError, ValueError):
            return False

    def _receptacle(self, receptacle_name: str, held: str) -> Receptacle:
        if receptacle_name == TABLE:
            return self._table_region()
        name = self._name(receptacle_name)
        if name == held:
            raise ValueError(f"cannot place {held!r} into itself")
        receptacle = self.perception.receptacle(name)
        if receptacle is None:
            containers = [n for n in self.perception.names() if self._holds_things(n)]
            raise ValueError(
                f"{name!r} cannot hold things; receptacles here: {', '.join([*containers, TABLE])}; or pass position="
            )
        if receptacle.upper[0] - receptacle.lower[0] < 0.04 and ".drawer_" in name:
            raise PlacementError(f"{name!r} is closed: open it before placing anything into it")
        _, _, half = self.perception.footprint(held)
        if not fits(receptacle, half):
            inner = receptacle.upper - receptacle.lower
            raise PlacementError(
                f"{held!r} ({half[0] * 200:.0f} x {half[1] * 200:.0f} cm) does not fit into {name!r}, "
                f"whose free interior is {inner[0] * 100:.0f} x {inner[1] * 100:.0f} cm"
            )
        return receptacle

    def _footprint(self, name: str) -> Footprint:
        center, yaw, half = self.perception.footprint(name)
        return Footprint(np.asarray(center, dtype=float), float(yaw), np.asarray(half, dtype=float))

    def _table_region(self) -> Receptacle:
        """Where things may be put aside on the table: its top as perception knows it, within the robot's reach."""
        table = self.perception.box(TABLE)
        reach_lower, reach_upper = self.base_xy + TABLE_REACH[0], self.base_xy + TABLE_REACH[1]
        lower = np.maximum(table.lower[:2], reach_lower)
        upper = np.minimum(table.upper[:2], reach_upper)
        top = float(table.upper[2])
        if np.any(upper <= lower):
            raise PlacementError(f"no part of the table {np.round(table.as_array(), 3).tolist()} is within reach")
        return Receptacle(TABLE, Transform.identity(), np.array([*lower, top]), np.array([*upper, top + 0.4]))

    def _first_reachable(self, name: str, candidates: list[Transform], kind: str) -> Transform:
        """The first candidate whose grasp and pre-grasp poses have collision-free IK (the gripper may touch the
        object itself); each is also tried turned half a turn about its approach axis."""
        q = self.motion.sync()
        errors: list[str] = []
        flip = Transform(np.zeros(3), np.array([0.0, 0.0, 1.0, 0.0]))
        fallback: Transform | None = None
        new = [n for n in self._grasp_family(name) if n not in self._touch_allowed and n not in self._held]
        with _touch(self.motion, new):
            for rank, candidate in enumerate(candidates):
                for pose in (candidate, candidate.compose(flip)):
                    try:
                        goal, approach = self.motion.straight_approach(
                            pose, PRE_GRASP_DISTANCE, q, attempts=8, max_attempts=40, branches=3
                        )
                        if approach is None and rank < WIDE_BRANCH_SEARCH:
                            # The IK branches nearest the arm's present configuration may all be walled in
                            # (an arm that has just put something down beside the cabinet): the best-ranked grasps
                            # are worth a wider search before a worse grasp is taken.
                            goal, approach = self.motion.straight_approach(
                                pose, PRE_GRASP_DISTANCE, q, attempts=8, max_attempts=80, branches=8
                            )
                    except IKError as exc:
                        errors.append(str(exc))
                        continue
                    if approach is None:
                        # Reachable, but grasp() will have to plan its final approach: kept as a last resort.
                        fallback = fallback or pose
                        errors.append("the straight approach from the pre-grasp pose is blocked on every IK branch")
                        continue
                    pull = self._pull_check(name, pose, goal)
                    if pull:
                        errors.append(pull)
                        continue
                    return pose
        if fallback is not None:
            return fallback
        raise PlanningError(
            f"none of the {len(candidates)} {kind} grasps of {name!r} (each also turned half a turn) can be reached "
            f"without collision; first failure: {errors[0] if errors else 'none'}",
        )

    def _pull_check(self, name: str, pose: Transform, q: np.ndarray) -> str:
        """For the handle of a drawer: why the arm could not pull it ``PULL_CHECK`` metres open from this grasp
        (empty if it could). A handle is grasped to be pulled, and a grasp that cannot pull is no use."""
        if ".handle_" not in name:
            return ""
        joints = self.perception.joints(name)
        if not joints or joints[0].type != "prismatic":
            return ""
        remaining = joints[0].upper - joints[0].value
        distance = min(PULL_CHECK, remaining)
        if distance < 0.02:
            return ""
        target = Transform(pose.position + joints[0].axis * distance, pose.quaternion)
        line = cartesian_path(self.motion.kinematics, self.motion.scene, q, [target])
        if line.fraction >= 1.0:
            return ""
        return f"from this grasp the drawer can be pulled only {line.fraction * distance * 100:.0f} cm: {line.reason}"

    def _grasp_family(self, name: str) -> list[str]:
        return self._part_family(name) if name not in self.perception.objects() else [name]

    def _fill_corner(self, receptacle: Receptacle) -> np.ndarray:
        """Where filling starts: the corner nearest the robot; for a drawer, the front corner nearest the robot
        (the back of an open drawer is under the carcass, where the arm has no room)."""
        if ".drawer_" not in receptacle.name:
            return self.base_xy
        lower, upper = receptacle.lower, receptacle.upper
        fronts = receptacle.frame.apply(np.array([[upper[0], lower[1], 0.0], [upper[0], upper[1], 0.0]]))[:, :2]
        return fronts[int(np.argmin(np.linalg.norm(fronts - self.base_xy, axis=1)))]

    def _reachable_place(
        self, name: str, tcp: Transform, pivot: np.ndarray, spots: list[PlacementSpot], where: str
    ) -> Transform:
        """The first spot (in order, skipping near-repeats of spots that failed) with a collision-free IK from which
        the hand can also retreat straight up (:data:`PLACE_RETREAT`), as a place's retreat would: a hand put
        down with a link against the cabinet has no way out but through what it let go. Each spot is tried with
        the object turned as the spot allows (round, or any quarter turn at a position), and released higher up
        so the hand clears a deep container's walls; of the turns and IK branches that work at a height, the one
        nearest the arm's present configuration is taken (a hand kept facing one way can make the arm swing
        round behind itself). Where no spot allows the retreat, the first reachable one is taken. The
        configuration chosen becomes the motion's goal for that pose (:meth:`MotionPlanner.prefer_goal`)."""
        q = self.motion.sync()
        tried: list[PlacementSpot] = []
        errors: list[str] = []
        fallback: tuple[Transform, np.ndarray] | None = None
        budget = PLACE_IK_BUDGET
        for spot in spots:
            if budget <= 0:
                break
            if any(np.linalg.norm(spot.center - t.center) < 0.05 and _same_turn(spot.yaw, t.yaw) for t in tried):
                continue
            tried.append(spot)
            for lift in (0.0, 0.02, 0.05, 0.1):
                reached = self._place_options(spot, lift, tcp, pivot, q, errors)
                budget -= len(spot.turns)
                fallback = fallback or next(((pose, goals[0]) for pose, goals in reached), None)
                leaving = [(pose, g) for pose, goals in reached for g in goals if self._can_retreat(pose, g)]
                if leaving:
                    pose, goal = min(leaving, key=lambda c: float(np.sum((c[1] - q) ** 2)))
                    self.motion.prefer_goal(pose, goal)
                    return pose
                if budget <= 0:
                    break
        if fallback is not None:
            self.motion.prefer_goal(*fallback)
            return fallback[0]
        raise PlacementError(
            f"no reachable, collision-free pose puts {name!r} {where} ({len(tried)} spots tried): "
            f"{errors[0] if errors else 'no spot'}"
        )

    def _place_options(
        self, spot: PlacementSpot, lift: float, tcp: Transform, pivot: np.ndarray, q: np.ndarray, errors: list[str]
    ) -> list[tuple[Transform, list[np.ndarray]]]:
        """The gripper poses that put the held object at ``spot`` (``lift`` higher), one per turn it allows, with
        their collision-free IK branches; the poses without any add their reason to ``errors``."""
        out = []
        for turn in spot.turns:
            rotation = quat_to_matrix(quat_from_yaw(spot.yaw + turn))
            # Turning the held object about world z around its middle turns the gripper with it.
            position = spot.center + [0.0, 0.0, lift] + rotation @ (tcp.position - pivot)
            pose = Transform.from_rotation(position, rotation @ tcp.rotation)
            try:
                out.append((pose, self.motion.ik_choices(pose, q, attempts=8, max_attempts=24)))
            except IKError as exc:
                errors.append(str(exc))
        return out

    def _can_retreat(self, pose: Transform, q: np.ndarray) -> bool:
        """Whether the arm at ``q`` (the TCP at ``pose``) can let go there, the fingers opening fully without
        touching anything but what they held, and then move straight up by :data:`PLACE_RETREAT` (what it held
        stays behind)."""
        up = Transform(pose.position + np.array([0.0, 0.0, PLACE_RETREAT]), pose.quaternion)
        scene = self.motion.scene
        with scene.ignoring_held(), scene.fingers_open():
            return cartesian_path(self.motion.kinematics, scene, q, [up]).fraction >= 1.0

    def _allow_touch_near(self, point: np.ndarray) -> None:
        """Lets the fingers touch what lies at the goal (the object to be grasped); withdrawn once clear of it.

        Not while holding something: then the goal is a place pose, and the fingers must keep clear of the
        receptacle."""
        if self._held:
            return
        scene = self.motion.scene
        for name in self._near(point):
            if name not in self._touch_allowed:
                for part in self._grasp_family(name):
                    scene.allow("gripper", part)
                self._touch_allowed.add(name)

    def _near(self, point: np.ndarray, distance: float = 0.02) -> list[str]:
        """Objects and furniture whose box is within ``distance`` of ``point`` (never the table, which everything
        low is near)."""
        out = []
        for name in [*self.perception.objects(), *self.perception.furniture()]:
            box = self.perception.box(name)
            gap = np.maximum(np.maximum(box.lower - point, point - box.upper), 0.0)
            if float(np.linalg.norm(gap)) < distance:
                out.append(name)
        return out

    def _new_touches(self, point: np.ndarray) -> list[str]:
        """Parts near ``point`` the gripper may not touch yet (for a temporary allowance)."""
        if self._held:
            return []
        names = [n for n in self._near(point) if n not in self._touch_allowed]
        return sorted({part for n in names for part in self._grasp_family(n)})

    def _allow_start_contacts(self) -> None:
        """Lets the gripper leave what it touches now (an object that settled against the fingers after being let
        go) until it has moved clear: the motion that leaves a contact must be allowed to start in it, though not
        to push deeper into it (a planned motion that swept the hand through what was just put down would knock
        it over)."""
        scene = self.motion.scene
        q = self.motion.sync()
        names = set(self.perception.names())
        for pair in scene.collisions(q):
            for name in pair:
                if name in names and scene.touching("gripper", name, q):
                    for part in self._grasp_family(name):
                        scene.allow_leaving("gripper", part, q)
                    self._touch_allowed.add(name)
        # An arm link can end a motion a few millimetres nearer furniture than planned (tracking), inside the
        # scene's padding; without this the next motion could not start at all.
        for pair in scene.collisions(q):
            scene.allow_leaving(*pair, q)
            self._link_contacts.add(pair)

    def _after_motion(self) -> None:
        """Withdraws touch allowances the gripper has moved clear of (never for what it holds)."""
        scene = self.motion.scene
        q = self.motion.sync()
        for pair in list(self._link_contacts):
            if not scene.touching(*pair, q):
                scene.allow(*pair, False)
                self._link_contacts.discard(pair)
        for name in list(self._touch_allowed):
            if name in self._held:
                continue
            family = self._grasp_family(name)
            if not any(scene.touching("gripper", part, q) for part in family):
                for part in family:
                    scene.allow("gripper", part, False)
                self._touch_allowed.discard(name)


class _touch:
    """Context: the gripper may touch these names while candidate grasps are checked."""

    # The motion, not its scene: a scene rebuilt within the block (a look on the way) carries the allowance over,
    # and it is withdrawn from the scene in use at the end.
    def __init__(self, motion, names: list[str]):
        self.motion, self.names = motion, names

    def __enter__(self):
        for name in self.names:
            self.motion.scene.allow("gripper", name)

    def __exit__(self, *exc):
        for name in self.names:
            self.motion.scene.allow("gripper", name, False)


def _clear_of(spots: list, points: np.ndarray, radius: float, table_top: float) -> list:
    """The spots with no observed point above the table within ``radius`` of their centre (on the table's level:
    the table itself and what hangs high above it do not count)."""
    band = points[(points[:, 2] > table_top + 0.005) & (points[:, 2] < table_top + 0.5)][:, :2]
    if len(band) == 0:
        return spots
    return [s for s in spots if float(np.min(np.linalg.norm(band - s.center[:2], axis=1))) > radius]


def _same_turn(a: float, b: float) -> bool:
    """Whether two yaw turns face the same way, or opposite ways (a spot tried both ways round already)."""
    return abs(math.remainder(a - b, math.pi)) < 0.1


def _overlaps_xy(box: Box3D, center: np.ndarray, half: np.ndarray) -> bool:
    return bool(np.all(np.abs(box.center[:2] - center) < box.size[:2] / 2 + half))


def _within(box: Box3D, receptacle: Receptacle) -> bool:
    """Whether an object's box centre lies in the receptacle's interior (in its frame)."""
    local = receptacle.frame.inverse().apply(box.center[None])[0]
    return bool(np.all(local >= receptacle.lower - 0.01) and np.all(local <= receptacle.upper + 0.01))


def _vector(value: object, field: str) -> np.ndarray:
    if isinstance(value, Pose):
        return value.position_array()
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{field} must be 3 numbers [x, y, z], got {type(value).__name__} {value!r}")
    try:
        array = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise TypeError(f"{field} must be 3 numbers [x, y, z], got {type(value).__name__} {value!r}") from None
    if array.shape != (3,):
        raise ValueError(f"{field} must be 3 numbers [x, y, z], got {array.size}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{field} must be finite, got {array.tolist()}")
    return array


def _direction(value: object, field: str) -> np.ndarray:
    vector = _vector(value, field)
    norm = float(np.linalg.norm(vector))
    if norm < 1e-9:
        raise ValueError(f"{field} must be a non-zero direction, got {vector.tolist()}")
    return vector / norm


def _pose(value: object, field: str) -> Transform:
    if not isinstance(value, Pose):
        raise TypeError(
            f"{field} must be a Pose (e.g. from get_gripper_pose() or a parse_* tool), got {type(value).__name__}"
        )
    return value.to_transform()


__all__ = ["PlanningError", "ToolAPI", "UnknownObjectError"]
