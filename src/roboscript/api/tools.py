"""The tool API: the functions a generated program calls (DESIGN.md §3), on a backend, perception and planner.

Every tool checks its arguments first and raises an error that names what was wrong and what would be valid; a
failed tool leaves the world as it was (nothing moves before a motion has been planned in full).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from roboscript.api.held import Held, PerceptionFollower, PlanningFollower
from roboscript.api.placement import Placer
from roboscript.api.pose import Pose, _real
from roboscript.api.signature import tool
from roboscript.api.spots import DROP
from roboscript.backends.base import Backend
from roboscript.geometry import Transform, rotation_angle_between
from roboscript.names import is_part, kind_of
from roboscript.notices import notice
from roboscript.perception.base import ObjectPoints, Perception, UnknownObjectError
from roboscript.perception.grasp_detection import (
    UNCLEAN_RELEASE_PENALTY,
    WIDTH_MARGIN,
    GraspPreferences,
    GripperGeometry,
    detect_grasps,
    falls_free,
    score_grasp,
)
from roboscript.perception.grasp_heuristics import GraspError, central_lift_grasps, horizontal_grasps
from roboscript.phases import timed
from roboscript.planning.cartesian import arc_poses
from roboscript.planning.contacts import ContactAllowances
from roboscript.planning.errors import IKError, PlanningError
from roboscript.planning.motion import MotionPlanner

PRE_GRASP_DISTANCE = 0.1
# A box grasp closes on the faces of the object's footprint, not on a pair of points checked against friction:
# ranked with the contact quality of a middling antipodal pair.
BOX_GRASP_QUALITY = 0.5
# Lower than this, an object lies flat (a banana, 3.8 cm): a side grasp tilted down onto it closes on the upper
# curve of its body and squeezes it out of the fingers, so the box side grasps rank behind the top-down ones.
LYING_FLAT = 0.05
LYING_SIDE_PENALTY = 1.5
# Retreats made on the program's behalf before its next motion, unless that motion is one itself: a held object is
# lifted off its support (up), a released one left behind (the hand backs off along its approach axis).
LIFT_AFTER_GRASP = 0.05
EMPTY_GRIP = 0.002  # metres: fingers closed this far hold nothing
RETREAT_AFTER_RELEASE = 0.05
RELEASE_CLEARANCE = 0.01  # beyond what was let go, where the fingertips end the release retreat if that is further
RELEASE_RETREAT_LEAST = 0.02  # a program's own retreat after a release may stop short of its distance, not of this
SAME_ORIENTATION = 0.05  # radians: a move_to_pose turning the hand less is a straight move, a retreat if it backs off
OWN_RETREAT = 0.5  # cosine (60 deg) above which a program's motion is its own retreat; wider than PREFERENCE_CONE
PULL_CHECK = 0.25  # metres a drawer handle grasp should be able to pull
PULL_LEAST = 0.15  # metres the grasp must pull where none pulls PULL_CHECK
JOINT_TYPES = ("any", "revolute", "prismatic")
FARTHEST_POSE = 10.0  # metres from the world's origin along any axis: every arm reaches less than one


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
        self.contacts = ContactAllowances(motion, self._grasp_family)
        self.held = Held([PlanningFollower(motion, self.contacts), PerceptionFollower(perception)])
        self.placer = Placer(perception, motion, self.base_xy)
        # Owed before the next motion: (direction, distance, "lift" after a grasp or "release" after letting go).
        self._pending_retreat: tuple[np.ndarray, float, str] | None = None

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
    @timed("grasp")
    def parse_central_lift_grasp_pose(self, object_name: str, description: str = "top") -> Pose:
        """A top-down grasp at the box centre in x, y; z near the top ("top") or at mid height ("center")."""
        name = self._name(object_name)
        candidates = central_lift_grasps(
            self.perception, name, description, self.gripper.max_width, self.base_xy, self._finger_reach
        )
        return Pose.from_transform(self._first_reachable(name, candidates, "central lift"))

    @tool
    @timed("grasp")
    def parse_horizontal_grasp_pose(self, object_name: str, approach_direction: Sequence[float] | None = None) -> Pose:
        """A grasp approaching horizontally (handles, upright objects), along ``approach_direction`` if given."""
        name = self._name(object_name)
        approach = None if approach_direction is None else _vector(approach_direction, "approach_direction")
        candidates = horizontal_grasps(self.perception, name, approach, self.gripper.max_width, self.base_xy)
        return Pose.from_transform(self._first_reachable(name, candidates, "horizontal"))

    @tool
    @timed("grasp")
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
        detected = detect_grasps(
            cloud, self.perception.scene_points(), self.gripper, preferences, seed=self.seed, release_drop=DROP
        )
        # The box grasps that fit the object compete too, ranked by the same score: where sampling finds pairs
        # only off the middle (a banana half hidden from the cameras) or none within reach (an object nearly as
        # wide as the opening), the adaptive grasp is then no worse than the central or horizontal one.
        width = self.gripper.max_width - WIDTH_MARGIN
        lying = self.perception.box(name).size[2] < LYING_FLAT
        ranked = [(c.score, c.pose) for c in detected[:12]] + [
            (
                score_grasp(pose, width, BOX_GRASP_QUALITY, cloud, preferences) - self._penalties(pose, cloud, lying),
                pose,
            )
            for pose in self._box_grasps(name, preferences)
        ]
        candidates = [pose for _, pose in sorted(ranked, key=lambda c: -c[0])]
        if not candidates:
            raise GraspError(
                f"no collision-free antipodal grasp found on {name!r} ({len(cloud.points)} points seen), and it is "
                f"wider than the gripper's {self.gripper.max_width * 100:.1f} cm opening across every side, so no "
                "central lift or horizontal grasp fits either"
            )
        return Pose.from_transform(self._first_reachable(name, candidates, "adaptive"))

    def _penalties(self, pose: Transform, cloud: ObjectPoints, lying: bool) -> float:
        """What a box grasp loses in rank: a side grasp of a flat-lying object, and one the object would not fall
        free of when let go (as :func:`detect_grasps` ranks its own)."""
        unclean = not falls_free(pose.rotation, pose.position, cloud.points, self.gripper, DROP)
        return _side_penalty(pose, lying) + (UNCLEAN_RELEASE_PENALTY if unclean else 0.0)

    def _box_grasps(self, name: str, preferences: GraspPreferences) -> list[Transform]:
        """The central lift and horizontal grasps that fit ``name``, in the order the preferred approach suggests
        (top-down first unless a horizontal approach is preferred)."""
        kinds = [
            lambda: central_lift_grasps(
                self.perception, name, "center", self.gripper.max_width, self.base_xy, self._finger_reach
            ),
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
        if self.held:  # what was let go stays behind
            back = -self.backend.tcp_pose().rotation[:, 2]
            self._pending_retreat = (back, self._release_retreat(back), "release")

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
        current = self.backend.tcp_pose()
        motion = target.position - current.position
        own = self._retreat_first(motion, shorter=True)
        self._leave_where_started()
        turned = rotation_angle_between(current.quaternion, target.quaternion)
        if own is not None and own[2] == "release" and turned < SAME_ORIENTATION and self._own_retreat(motion, own):
            return
        self._allow_touch_near(target.position)
        try:
            self.motion.move_to_pose(target)
        except IKError as exc:
            higher = self.placer.raised_for_release(target, exc, self.held)
            if higher is None:
                raise
            notice(
                f"move_to_pose: {', '.join(self.held)} sits lower in the hand than when the pose was made: "
                f"going {higher.position[2] - target.position[2]:.3f} m higher"
            )
            self.motion.move_to_pose(higher)
        self.contacts.withdraw_cleared(self.held)

    @tool
    def move_in_direction(self, axis: Sequence[float], distance: float) -> None:
        """Moves the TCP in a straight line along ``axis`` by ``distance`` metres, keeping its orientation."""
        direction = _direction(axis, "axis")
        distance = _real(distance, "distance")
        if abs(distance) > 1.5:
            raise ValueError(f"distance is in metres and must be within [-1.5, 1.5], got {distance}")
        own = self._retreat_first(direction * distance, shorter=True)
        self._leave_where_started()
        if own is not None and own[2] == "release" and self._own_retreat(direction * distance, own):
            return
        self.motion.move_in_direction(direction, distance, plan_if_blocked=True)
        self.contacts.withdraw_cleared(self.held)

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
        self._leave_where_started()
        self.motion.follow(targets)
        self.contacts.withdraw_cleared(self.held)

    @tool
    def grasp(self, grasp_pose: Pose) -> None:
        """Moves to a pre-grasp pose 0.1 m back along the approach axis, then straight to ``grasp_pose``.

        The gripper is not closed; call ``close_gripper()`` next.
        """
        target = _pose(grasp_pose, "grasp_pose")
        # The way to the pre-grasp is planned, not straight: it is never the retreat itself, whatever its direction.
        self._retreat_first(None)
        self._leave_where_started()
        # The fingers may touch the object only on the final straight approach, not on the way to its start.
        with self.contacts.touching(self._new_touches(target.position)):
            options = self.motion.approaches(target, PRE_GRASP_DISTANCE)
        chosen = self.motion.move_to_approach(options, target, PRE_GRASP_DISTANCE)
        self._allow_touch_near(target.position)
        self.motion.finish_approach(chosen, target)
        self.contacts.withdraw_cleared(self.held)

    @tool
    @timed("place")
    def parse_place_pose(
        self, object_name: str, receptacle_name: str | None = None, position: Sequence[float] | None = None
    ) -> Pose:
        """A reachable gripper pose that puts the held object into/onto the receptacle, or at ``position``."""
        name = self._name(object_name)
        if (receptacle_name is None) == (position is None):
            raise ValueError(
                "give exactly one of receptacle_name (e.g. 'plate', 'cabinet.drawer_1') or position [x, y, z]"
            )
        if name not in self.held:
            held = ", ".join(self.held.names) or "nothing"
            raise ValueError(
                f"parse_place_pose needs {name!r} in the gripper (it holds {held}): grasp it, close_gripper() and "
                f"attach_object({name!r}) first"
            )
        target = None if position is None else _vector(position, "position")
        spots, where = self.placer.spots(name, receptacle_name, target)
        return Pose.from_transform(self.placer.reachable(name, self.backend.tcp_pose(), spots, where))

    @tool
    def attach_object(self, object_name: str) -> None:
        """Makes the planning scene carry ``object_name`` with the gripper (after closing on it)."""
        name = self._name(object_name)
        if name in self.held:
            return
        is_object = name in self.perception.objects()
        if not is_object and "." not in name:
            movable = [n for n in self.perception.furniture() if "." in n]
            raise ValueError(
                f"{name!r} cannot be held: it does not move. Attach what the gripper holds: an object "
                f"({', '.join(self.perception.objects()) or 'none'}) or a drawer or door, or its handle "
                f"({', '.join(movable) or 'none'})"
            )
        self.held.take(name, is_object, self.backend.tcp_pose())
        if not is_object:
            return
        # Off whatever it rests on, at once if the fingers hold it: where it settles in the hand, and so what a
        # place pose asked for next must allow for, shows only once it hangs free.
        self._pending_retreat = (np.array([0.0, 0.0, 1.0]), LIFT_AFTER_GRASP, "lift")
        if self.backend.gripper_width() < self.gripper.max_width - 0.005:
            self._retreat_first(None)
            if self.backend.gripper_width() < EMPTY_GRIP:
                self.held.let_go(name, self.backend.tcp_pose())
                raise GraspError(
                    f"{name!r} is not between the fingers: they closed on nothing as the hand lifted it (the grasp "
                    "missed, or it slipped out). Open the gripper and grasp it again: nearer its middle, or from "
                    "above (preferred_approach_direction=[0, 0, -1])"
                )
            if self.perception.hangs_free(name):
                self.motion.world_changed()  # the planning scene carries it as it hangs

    @tool
    def detach_object(self, object_name: str) -> None:
        """Returns ``object_name`` to the planning scene's world (after opening the gripper)."""
        self.held.let_go(self._name(object_name), self.backend.tcp_pose())

    # --- internals -------------------------------------------------------------------------------------------

    def _own_retreat(self, motion: np.ndarray, owed: tuple[np.ndarray, float, str]) -> bool:
        """The program's own straight retreat from what it just let go of, as far as reach allows: an opened
        drawer's handle, or a place pose in a high drawer, may stand at the edge of the workspace, and the
        retreat's purpose (clearing what was let go) is met before its end. A retreat shorter than the ``owed``
        one is made as long as that: its purpose is the same, and ending a few millimetres past the program's pose
        is nearer to it than making both (a mug let go in a high drawer: the owed 5.7 cm and the program's 5 cm
        up were out of reach together). False where not even :data:`RELEASE_RETREAT_LEAST` is free: the ``owed``
        retreat is then made, and the caller moves as it would have."""
        distance = max(float(np.linalg.norm(motion)), owed[1])
        moved = self.motion.retreat(motion, distance, least=min(RELEASE_RETREAT_LEAST, distance))
        if moved <= 0.0:
            self.motion.retreat(*owed[:2])
            return False
        if moved < distance - 1e-3:
            notice(f"retreat: backed off {moved:.3f} m of {distance:.3f} m: the rest is out of reach")
        self.contacts.withdraw_cleared(self.held)
        return True

    def _release_retreat(self, back: np.ndarray) -> float:
        """How far the hand backs out along ``back`` after letting go: :data:`RETREAT_AFTER_RELEASE`, or until the
        fingertips have passed what was let go by :data:`RELEASE_CLEARANCE`. A cup let go from the side reaches
        6 cm back from the TCP: fingertips stopped at its near wall caught its flared rim as the hand rose."""
        tcp = self.backend.tcp_pose().position
        reach = 0.0
        for name in self.held.objects:
            points = self.perception.points(name).points
            if len(points):
                reach = max(reach, float(np.max((points - tcp) @ back)))
        return max(RETREAT_AFTER_RELEASE, reach + self.gripper.tip_length + RELEASE_CLEARANCE)

    def _retreat_first(self, motion: np.ndarray | None, shorter: bool = False) -> tuple[np.ndarray, float, str] | None:
        """Makes the retreat owed since the last grasp or release, unless ``motion`` (the program's next straight
        move, as a displacement of the TCP; None for a planned one) is already one: mostly along the retreat, and
        at least as long, or, with ``shorter``, after a release, of any length (the caller then makes it as long
        as the owed one, :meth:`_own_retreat`). Returns the retreat not made, ``(direction, distance, kind)`` with
        kind "lift" or "release", when ``motion`` is the program's own retreat, else None."""
        pending, self._pending_retreat = self._pending_retreat, None
        if pending is None:
            return None
        direction, distance, kind = pending
        length = 0.0 if motion is None else float(np.linalg.norm(motion))
        # Away from what was let go is back along the approach, or up: a hand that let go beside something
        # leaves it as well upwards.
        away = [direction] if kind == "lift" else [direction, np.array([0.0, 0.0, 1.0])]
        long_enough = length >= distance or (shorter and kind == "release")
        if length > 0.0 and long_enough and any(float(a @ motion) / length > OWN_RETREAT for a in away):
            return pending
        self._leave_where_started()
        self.motion.retreat(direction, distance)
        self.contacts.withdraw_cleared(self.held)
        return None

    def _name(self, name: object) -> str:
        return self.perception.require(name)

    def _part_family(self, name: str) -> list[str]:
        """A part with its handle and the part the handle is on (``cabinet.drawer_1`` <-> ``cabinet.handle_1``)."""
        family = {name}
        for joint in self.perception.joints(name):
            family.add(joint.part)
        prefix = name.rpartition(".")[0]
        if is_part(name):
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

    @property
    def _finger_reach(self) -> float:
        """How far the fingers reach from the TCP back to the hand (how deep a top-down grasp may take an object)."""
        return -self.gripper.hand_upper[2]

    def _first_reachable(self, name: str, candidates: list[Transform], kind: str) -> Transform:
        """The first candidate whose grasp and pre-grasp poses have collision-free IK (the gripper may touch the
        object itself); each is also tried turned half a turn about its approach axis."""
        q = self.motion.sync()
        errors: list[str] = []
        flip = Transform(np.zeros(3), np.array([0.0, 0.0, 1.0, 0.0]))
        fallback: Transform | None = None
        short_pull: tuple[float, Transform] | None = None
        walled: Transform | None = None
        short_approach: Transform | None = None
        with self.contacts.touching(self.contacts.not_yet_allowed([name], self.held)):
            for candidate in candidates:
                for pose in (candidate, candidate.compose(flip)):
                    # Every grasp's IK branches are searched widely before a worse grasp is taken: next to the
                    # base the arm is folded near its joint limits, and the nearest branches cannot follow even a
                    # top-down line (a banana beside the Panda: a grasp at its end was taken instead, and the
                    # banana swung out of the fingers).
                    try:
                        goal, approach = self.motion.approaches(
                            pose, PRE_GRASP_DISTANCE, q, attempts=8, max_attempts=40, branches=3, first=True
                        )[0]
                    except IKError as exc:
                        errors.append(str(exc))
                        continue
                    if approach is None:
                        # Reachable, but grasp() will have to plan its final approach: kept as a last resort.
                        fallback = fallback or pose
                        errors.append("the straight approach from the pre-grasp pose is blocked on every IK branch")
                        continue
                    pulled, why = self._pull_reach(name, pose, goal)
                    if why:
                        errors.append(why)
                        if pulled >= PULL_LEAST and (short_pull is None or pulled > short_pull[0]):
                            short_pull = (pulled, pose)
                        continue
                    if self.motion.approach_length(approach) < PRE_GRASP_DISTANCE - 1e-3:
                        # Moved in along a shortened line: kept, in case no grasp has the full approach.
                        errors.append("the straight approach is free only part of the way")
                        short_approach = short_approach or pose
                        continue
                    if not self.motion.connects(q, approach[0]):
                        # IK reaches its pre-grasp, but no path was found to it: a configuration walled in by
                        # the table. Kept, in case the planner's retries would find one.
                        errors.append("no path was found to the pre-grasp configuration")
                        walled = walled or pose
                        continue
                    return pose
        # The last resorts, best first. A handle grasp that pulls less than PULL_CHECK is kept over one that
        # cannot move in straight: the program may not pull that far (a preferred approach costs reach).
        for kept in (walled, short_approach, short_pull[1] if short_pull else None, fallback):
            if kept is not None:
                return kept
        raise PlanningError(
            f"none of the {len(candidates)} {kind} grasps of {name!r} (each also turned half a turn) can be reached "
            f"without collision; first failure: {errors[0] if errors else 'none'}",
        )

    def _pull_reach(self, name: str, pose: Transform, q: np.ndarray) -> tuple[float, str]:
        """For the handle of a drawer: how far the arm can pull it open from this grasp, up to ``PULL_CHECK``
        metres, and why not further (empty if it can pull that far). A handle is grasped to be pulled, and a
        grasp that cannot pull is no use."""
        if kind_of(name) != "handle":
            return 0.0, ""
        joints = self.perception.joints(name)
        if not joints or joints[0].type != "prismatic":
            return 0.0, ""
        remaining = joints[0].upper - joints[0].value
        distance = min(PULL_CHECK, remaining)
        if distance < 0.02:
            return distance, ""
        target = Transform(pose.position + joints[0].axis * distance, pose.quaternion)
        line = self.motion.cartesian([target], start=q)
        if line.fraction >= 1.0:
            return distance, ""
        pulled = line.fraction * distance
        return pulled, f"from this grasp the drawer can be pulled only {pulled * 100:.0f} cm: {line.reason}"

    def _grasp_family(self, name: str) -> list[str]:
        return self._part_family(name) if name not in self.perception.objects() else [name]

    def _allow_touch_near(self, point: np.ndarray) -> None:
        """Lets the fingers touch what lies at the goal (the object to be grasped); withdrawn once clear of it.

        Not while holding something: then the goal is a place pose, and the fingers must keep clear of the
        receptacle."""
        if not self.held:
            self.contacts.allow_touch(self._near(point))

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
        return [] if self.held else self.contacts.not_yet_allowed(self._near(point))

    def _leave_where_started(self) -> None:
        """Before a motion: contacts it starts in may be left, not pushed into (:class:`ContactAllowances`)."""
        self.contacts.leave_where_started(set(self.perception.names()))


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
    far = float(np.max(np.abs(value.position_array())))
    if far > FARTHEST_POSE:  # a straight path there is interpolated in steps of millimetres: bounded work only
        raise ValueError(
            f"{field} is {far:.3g} m from the world's origin; poses are in metres and within {FARTHEST_POSE:g} m of it"
        )
    return value.to_transform()


def _side_penalty(pose: Transform, lying: bool) -> float:
    """What a box grasp loses in rank for coming at a flat-lying object from the side (see :data:`LYING_FLAT`)."""
    top_down = -float(pose.rotation[2, 2]) > 0.95
    return LYING_SIDE_PENALTY if lying and not top_down else 0.0


__all__ = ["PlanningError", "ToolAPI", "UnknownObjectError"]
