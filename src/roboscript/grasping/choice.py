"""Grasp choice: the grasp tools' candidates ranked and screened for reach, the first the arm can take.

Candidates come from :mod:`roboscript.grasping.heuristics` (box grasps: top-down, horizontal) and
:mod:`roboscript.grasping.detection` (antipodal pairs over the observed points); this module asks the motion planner
which of them the arm reaches, with a straight approach and, for a drawer's handle, room to pull.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection

import numpy as np

from roboscript.geometry import Transform
from roboscript.grasping.detection import (
    UNCLEAN_RELEASE_PENALTY,
    WIDTH_MARGIN,
    GraspPreferences,
    GripperGeometry,
    detect_grasps,
    falls_free,
    score_grasp,
)
from roboscript.grasping.heuristics import GraspError, central_lift_grasps, horizontal_grasps
from roboscript.names import kind_of
from roboscript.notices import notice
from roboscript.perception.base import ObjectPoints, Perception
from roboscript.planning.approaches import approach_length, approaches
from roboscript.planning.cartesian import arc_poses
from roboscript.planning.contacts import ContactAllowances
from roboscript.planning.errors import IKError, PlanningError
from roboscript.planning.ik import IKSearch
from roboscript.planning.motion import MotionPlanner

PRE_GRASP_DISTANCE = 0.1
GRASP_APPROACH_SEARCH = IKSearch(8, 40, 3)  # every grasp's IK branches, searched before a worse grasp is taken
# A box grasp closes on the faces of the object's footprint, not on a pair of points checked against friction:
# ranked with the contact quality of a middling antipodal pair.
BOX_GRASP_QUALITY = 0.5
# Lower than this, an object lies flat (a banana, 3.8 cm): a side grasp tilted down onto it closes on the upper
# curve of its body and squeezes it out of the fingers, so the box side grasps rank behind the top-down ones.
LYING_FLAT = 0.05
LYING_SIDE_PENALTY = 1.5
PULL_CHECK = 0.25  # metres a drawer handle grasp should be able to pull
SWING_CHECK = math.radians(70)  # how far a door handle grasp should be able to swing its door open
SWING_STEPS = 14  # poses along that arc checked
PULL_LEAST = 0.6  # of PULL_CHECK or SWING_CHECK, what the grasp must open where none opens it in full
ADAPTIVE_DETECTED = 12  # antipodal grasps ranked against the box grasps
FLIP = Transform(np.zeros(3), np.array([0.0, 0.0, 1.0, 0.0]))  # half a turn about the approach axis


class GraspChooser:
    """The grasp tools' choice for one arm: ``held`` says what the hand holds now (the fingers may touch the
    object to be grasped, not what is held); ``release_drop``: how far above its support a thing is let go."""

    def __init__(
        self,
        perception: Perception,
        motion: MotionPlanner,
        contacts: ContactAllowances,
        gripper: GripperGeometry,
        base_xy: np.ndarray,
        held: Callable[[], Collection[str]],
        release_drop: float,
        seed: int = 0,
    ):
        self.perception, self.motion, self.contacts, self.gripper = perception, motion, contacts, gripper
        self.base_xy, self.held, self.release_drop, self.seed = base_xy, held, release_drop, seed

    @property
    def finger_reach(self) -> float:
        """How far the fingers reach from the TCP back to the hand (how deep a top-down grasp may take an object)."""
        return -self.gripper.hand_upper[2]

    def central(self, name: str, description: str) -> Transform:
        """A top-down grasp at the object's middle; where none the arm can take (the hand's end over a neighbour
        on every side that fits between the fingers), the best grasp of its shape instead, with a notice, as
        :meth:`horizontal` does: the program asked for a way to pick the object up."""
        try:
            candidates = central_lift_grasps(
                self.perception, name, description, self.gripper.max_width, self.base_xy, self.finger_reach
            )
            return self.first_reachable(name, candidates, "central lift")
        except PlanningError as failure:
            return self._shape_instead(name, failure, "parse_central_lift_grasp_pose", "")

    def horizontal(self, name: str, approach: np.ndarray | None) -> Transform:
        """A level (or tilted) grasp; for an object none of which the arm can take (a cup whose rim is wider than
        the Panda's opening, its body too near the table for the wrist), the best grasp of its shape instead, with
        a notice: the program asked for a way to pick the object up, and a refusal would leave it none."""
        # A preferred approach is preferred, not demanded: the approaches the tool would take by itself follow (a
        # drawer pulled out brings its handle to where only a wider turn reaches it).
        failure: GraspError | PlanningError | None = None
        tries = [(approach, False)] if approach is None else [(approach, False), (None, False)]
        if kind_of(name) != "handle":  # a handle is taken square to its front or not at all
            tries.append((None, True))
        for wanted, far in tries:
            try:
                candidates = horizontal_grasps(
                    self.perception, name, wanted, self.gripper.max_width, self.base_xy, far=far
                )
                return self.first_reachable(name, candidates, "horizontal")
            except (GraspError, PlanningError) as exc:
                failure = failure or exc
        # From above: a rim taken from the side leaves a finger hooked inside the cup when it is let go.
        return self._shape_instead(name, failure, "parse_horizontal_grasp_pose", " from above")

    def _shape_instead(self, name: str, failure: GraspError | PlanningError, tool: str, said: str) -> Transform:
        """The best grasp of the object's shape, approached from above, where ``tool``'s own grasps failed, with a
        notice that says why (``said``: how the notice names the approach); ``failure`` again for what is no
        object (a handle)."""
        if name not in self.perception.objects():
            raise failure
        why = str(failure).split("; the nearest to it")[0]
        pose = self.adaptive(name, GraspPreferences(approach=np.array([0.0, 0.0, -1.0])))
        notice(f"{tool}: {why}; taking the best grasp of its shape{said} instead")
        return pose

    def adaptive(self, name: str, preferences: GraspPreferences) -> Transform:
        """Antipodal grasps over the observed points, ranked together with the box grasps that fit by one score:
        where sampling finds pairs only off the middle (a banana half hidden from the cameras) or none within
        reach (an object nearly as wide as the opening), the adaptive grasp is no worse than the box ones."""
        cloud = self.perception.points(name)
        if len(cloud.points) < 10:
            raise GraspError(
                f"{name!r} is hardly visible to the cameras ({len(cloud.points)} points): no grasp detected"
            )
        detected = detect_grasps(
            cloud,
            self.perception.scene_points(),
            self.gripper,
            preferences,
            seed=self.seed,
            release_drop=self.release_drop,
        )
        width = self.gripper.max_width - WIDTH_MARGIN
        lying = self.perception.box(name).size[2] < LYING_FLAT
        ranked = [(c.score, c.pose) for c in detected[:ADAPTIVE_DETECTED]] + [
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
        return self.first_reachable(name, candidates, "adaptive")

    def _penalties(self, pose: Transform, cloud: ObjectPoints, lying: bool) -> float:
        """What a box grasp loses in rank: a side grasp of a flat-lying object, and one the object would not fall
        free of when let go (as :func:`detect_grasps` ranks its own)."""
        unclean = not falls_free(pose.rotation, pose.position, cloud.points, self.gripper, self.release_drop)
        return side_penalty(pose, lying) + (UNCLEAN_RELEASE_PENALTY if unclean else 0.0)

    def _box_grasps(self, name: str, preferences: GraspPreferences) -> list[Transform]:
        """The central lift and horizontal grasps that fit ``name``, in the order the preferred approach suggests
        (top-down first unless a horizontal approach is preferred)."""
        kinds = [
            lambda: central_lift_grasps(
                self.perception, name, "center", self.gripper.max_width, self.base_xy, self.finger_reach
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

    def first_reachable(self, name: str, candidates: list[Transform], kind: str) -> Transform:
        """The first candidate whose grasp and pre-grasp poses have collision-free IK (the gripper may touch the
        object itself); each is also tried turned half a turn about its approach axis. A handle's grasp should
        also be able to open its drawer or door (:meth:`_opening_reach`): the wrist turned near its limit on one
        of the two turns cannot follow a door's arc; and its open fingers should come in clear of the part's front
        (:meth:`_clear_of_panel`), or they push a door swung wide away on the way to its handle."""
        q = self.motion.sync()
        errors: list[tuple[int, str]] = []  # (how far the grasp got: 0 no IK ... 4 no path, why not further)
        fallback: Transform | None = None
        handle = kind_of(name) == "handle"
        short_pull: tuple[float, Transform] | None = None
        little_pull: tuple[float, Transform, str] | None = None
        walled: Transform | None = None
        short_approach: Transform | None = None
        pushes: Transform | None = None
        with self.contacts.touching(self.contacts.not_yet_allowed([name], self.held())):
            for candidate in candidates:
                for pose in (candidate, candidate.compose(FLIP)):
                    # Every grasp's IK branches are searched widely before a worse grasp is taken: next to the
                    # base the arm is folded near its joint limits, and the nearest branches cannot follow even a
                    # top-down line (a banana beside the Panda: a grasp at its end was taken instead, and the
                    # banana swung out of the fingers).
                    try:
                        options = approaches(
                            self.motion, pose, PRE_GRASP_DISTANCE, q, GRASP_APPROACH_SEARCH, first=not handle
                        )
                    except IKError as exc:
                        errors.append((0, str(exc)))
                        continue
                    if options[0][1] is None:
                        # Reachable, but grasp() will have to plan its final approach: kept as a last resort.
                        fallback = fallback or pose
                        errors.append((1, "the straight approach from the pre-grasp pose is blocked on every branch"))
                        continue
                    approach, pulled, why = self._branch_that_opens(name, pose, options)
                    if handle and not self._clear_of_panel(name, approach):
                        # The open fingers come at the bar across the door's or drawer's front and would push it
                        # (a door swung 75 degrees, taken from far round): kept, in case every grasp does.
                        errors.append((2, "the open fingers would push its door or drawer on the way in"))
                        pushes = pushes or pose
                        continue
                    if why:
                        errors.append((2, why))
                        if pulled >= PULL_LEAST and (short_pull is None or pulled > short_pull[0]):
                            short_pull = (pulled, pose)
                        elif pulled > 0.0 and (little_pull is None or pulled > little_pull[0]):
                            little_pull = (pulled, pose, why)
                        continue
                    if approach_length(self.motion, approach) < PRE_GRASP_DISTANCE - 1e-3:
                        # Moved in along a shortened line: kept, in case no grasp has the full approach.
                        errors.append((3, "the straight approach is free only part of the way"))
                        short_approach = short_approach or pose
                        continue
                    if not self.motion.connects(q, approach[0]):
                        # IK reaches its pre-grasp, but no path was found to it: a configuration walled in by
                        # the table. Kept, in case the planner's retries would find one.
                        errors.append((4, "no path was found to the pre-grasp configuration"))
                        walled = walled or pose
                        continue
                    return pose
        # The last resorts, best first. A handle grasp that pulls less than PULL_CHECK is kept over one that
        # cannot move in straight: the program may not pull that far (a preferred approach costs reach). One that
        # pulls less than PULL_LEAST comes after them, with a notice; one with no straight way in, last.
        for kept in (walled, short_approach, short_pull[1] if short_pull else None):
            if kept is not None:
                return kept
        if little_pull is not None:
            # A door swung to the edge of the arm's reach opens little further from any grasp: the one that opens
            # it furthest still takes the handle, to close it or to open it as far as the arm goes; it moves in
            # straight, where the last resort below does not.
            notice(f"{kind} grasp of {name!r}: {little_pull[2]}; no grasp opens it further")
            return little_pull[1]
        if pushes is not None:  # the door or drawer would be pushed: a TrackingError unless it gives way
            return pushes
        if fallback is not None:
            return fallback
        # The failure of the grasp that got furthest says most: a handle's head-on grasp is reached, but its door
        # swings no further from it, where the other grasps have no IK at all.
        nearest = max(errors, key=lambda e: e[0])[1] if errors else "none"
        raise PlanningError(
            f"none of the {len(candidates)} {kind} grasps of {name!r} (each also turned half a turn) can be reached "
            f"without collision; the nearest to it: {nearest}",
        )

    def _clear_of_panel(self, name: str, line: np.ndarray) -> bool:
        """Whether the gripper moves in along ``line`` (joint waypoints) to the handle ``name`` without touching the
        front of the part it opens: the grasp may touch the whole part (what moves with the handle), but only the
        bar is to be gripped."""
        panels = [p for p in self.contacts.family(name) if kind_of(p) != "handle"]
        with self.contacts.withheld(panels):
            return all(self.motion.scene.is_valid(q) for q in line)

    def _branch_that_opens(
        self, name: str, pose: Transform, options: list[tuple[np.ndarray, np.ndarray | None]]
    ) -> tuple[np.ndarray, float, str]:
        """Of a grasp's IK branches (``options``, nearest first; the first has a clear approach), the first with a
        clear approach from which a handle's drawer or door opens in full (:meth:`_opening_reach`), made the
        grasp's goal for ``pose``: its approach line, how far it opens and why not further; else the nearest's.
        A UR5e's nearest branch at a door's level handle turns its wrist into its forearm a quarter of the way
        round, where another swings the door wide."""
        clear = [(goal, line) for goal, line in options if line is not None]
        nearest = self._opening_reach(name, pose, clear[0][0])
        if not nearest[1]:
            return clear[0][1], *nearest
        for goal, line in clear[1:]:
            opened, why = self._opening_reach(name, pose, goal)
            if not why:
                self.motion.preferences.prefer(pose, goal)
                return line, opened, why
        return clear[0][1], *nearest

    def _opening_reach(self, name: str, pose: Transform, q: np.ndarray) -> tuple[float, str]:
        """For the handle of a drawer or a door: the share of ``PULL_CHECK`` metres (a drawer) or
        ``SWING_CHECK`` (a door, along the arc about its hinge) the arm can open it from this grasp, and why not
        further (empty if it can open it that far). A handle is grasped to be pulled, and a grasp that cannot pull
        is no use."""
        if kind_of(name) != "handle":
            return 0.0, ""
        joints = self.perception.joints(name)
        if not joints:
            return 0.0, ""
        joint = joints[0]
        remaining = joint.upper - joint.value
        if joint.type == "prismatic":
            distance = min(PULL_CHECK, remaining)
            if distance < 0.02:
                return 1.0, ""
            line = self.motion.cartesian([Transform(pose.position + joint.axis * distance, pose.quaternion)], start=q)
            what = f"the drawer can be pulled only {line.fraction * distance * 100:.0f} cm"
        else:
            angle = min(SWING_CHECK, remaining)
            if angle < math.radians(5):
                return 1.0, ""
            arc = arc_poses(pose, np.asarray(joint.axis), np.asarray(joint.position), SWING_STEPS, angle)
            with self.contacts.part_moving(joint.part, q, held=False):
                line = self.motion.cartesian(arc, start=q)
            what = f"the door can be swung only {math.degrees(line.fraction * angle):.0f} degrees"
        if line.fraction >= 1.0:
            return 1.0, ""
        return line.fraction, f"from this grasp {what}: {line.reason}"


def side_penalty(pose: Transform, lying: bool) -> float:
    """What a box grasp loses in rank for coming at a flat-lying object from the side (see :data:`LYING_FLAT`)."""
    top_down = -float(pose.rotation[2, 2]) > 0.95
    return LYING_SIDE_PENALTY if lying and not top_down else 0.0
