"""Placement search: the gripper pose that puts a held object where :mod:`roboscript.api.place_requests` says it
may go, reachable and with room for the hand to let go and back away.

This module asks the motion planner what the arm can reach: upright, raised, or leaning toward a spot's open side.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Collection

import numpy as np

from roboscript.api.nearby import MOVED, NEAR_BASE, distance_moved, near_base
from roboscript.api.place_requests import (
    PLACE_IK_BUDGET,
    REPEAT_SPACING,
    UP,
    PlacementError,
    PlaceRequest,
    PlaceRequests,
)
from roboscript.api.spots import PlacementSpot
from roboscript.geometry import Transform, quat_from_axis_angle, quat_from_yaw, quat_to_matrix
from roboscript.notices import notice
from roboscript.perception.base import Perception
from roboscript.planning.cartesian import cartesian_path
from roboscript.planning.errors import IKError
from roboscript.planning.ik import IKSearch
from roboscript.planning.motion import MotionPlanner
from roboscript.planning.scene_variants import fingers_open, ignoring_held

PLACE_PATH_SCREENS = 3  # planner runs per parse_place_pose call that check a place configuration can be reached
PLACE_IK_QUICK = IKSearch(8, 24)  # the IK search per place pose screened
PLACE_IK_WIDE = IKSearch(24, 200)  # the same where the quick screen reached no spot
PLACE_RAISE_LIMIT = 0.04  # metres a place pose is raised at most when the held object has sunk in the hand
# How much higher than resting a held object is tried, lowest first: a longer drop topples tall things.
PLACE_LIFTS = (0.0, 0.01, 0.02, 0.05, 0.1)
PLACE_LOW_LIFTS = PLACE_LIFTS[:3]  # tried first on the first few spots (PLACE_LOW_SPOTS)
PLACE_LOW_SPOTS = 4
PLACE_LOW_RADIUS = 0.03  # metres from the first spot within which those spots lie
PLACE_LOW_SPACING = 0.01  # metres those spots stand apart at least (turned the same way)
PLACE_RETREAT = 0.10  # metres a place pose should leave straight above it: the customary pre-place approach and retreat
# Where no upright pose reaches any spot (a drawer beneath another, at the edge of the arm's reach), the hand leans
# this far (degrees) toward the spot's open side, the held object with it, and lets go of it there: an object
# released a few degrees off upright lands on its lower edge and settles back onto its base.
PLACE_LEANS = (20.0, 35.0)
LEVEL_PITCH = 5.0  # degrees below level under which a hand counts as level


@dataclasses.dataclass(frozen=True)
class _Carried:
    """The held object as the hand carries it now: the TCP, the middle the object is turned about, and its box's
    corners about that middle."""

    tcp: Transform
    pivot: np.ndarray
    corners: np.ndarray

    def sink(self, rotation: np.ndarray) -> float:
        """How much lower than now the object's lowest corner reaches once turned by ``rotation`` about the
        pivot (0 for a turn about the vertical)."""
        return float(self.corners[:, 2].min() - (self.corners @ rotation.T)[:, 2].min())


@dataclasses.dataclass
class _Search:
    """What one pass over the spots found: a pose (with its configuration) that leaves the full retreat, the one
    that leaves the longest (``room`` metres), how many spots were tried, and why poses were out of reach."""

    leaving: tuple[Transform, np.ndarray, PlacementSpot] | None = None
    longest: tuple[Transform, np.ndarray, PlacementSpot] | None = None
    room: float = 0.0
    tried: int = 0
    errors: list[str] = dataclasses.field(default_factory=list)
    screens: int = PLACE_PATH_SCREENS  # planner runs left to check that a pose can be reached
    connected: bool = False  # whether a planner run reached ``leaving``


class Placer:
    """Placement search for the arm whose base stands at ``base_xy``."""

    def __init__(
        self,
        perception: Perception,
        motion: MotionPlanner,
        base_xy: np.ndarray,
        taken_from: Callable[[str], np.ndarray | None] = lambda name: None,
    ):
        """``taken_from``: where (x, y) the hand took a held object (:meth:`Held.taken_from`)."""
        self.perception = perception
        self.motion = motion
        self.base_xy = np.asarray(base_xy, dtype=float)
        self.taken_from = taken_from
        self.requests = PlaceRequests(perception, self.base_xy)

    def reachable(self, name: str, tcp: Transform, request: PlaceRequest) -> tuple[Transform, PlacementSpot]:
        """The gripper pose, from the hand at ``tcp`` holding ``name``, for the first of ``spots`` the arm can
        reach and leave; the configuration chosen becomes the motion's goal for that pose
        (:meth:`~roboscript.planning.goal_preferences.GoalPreferences.prefer`).

        In order of preference: an upright pose that leaves the full retreat (:data:`PLACE_RETREAT`) and that
        one planner run reaches (see :meth:`_search`), or failing a path, one that leaves the retreat; the same
        with the hand leaning toward the spot's open side (:data:`PLACE_LEANS`); an upright pose that leaves the
        longest retreat; an upright pose found by a wider IK search; a leaning pose that leaves the longest
        retreat. Into a compartment, with the hand pitched down, a levelled pose that leaves the retreat comes
        first."""
        # Spots are where the middle of the object's footprint goes (for a curved banana lying turned, not the
        # middle of its world-aligned box): the hand turns about that.
        footprint_center = self.perception.footprint(name)[0]
        box = self.perception.box(name)
        pivot = np.array([footprint_center[0], footprint_center[1], box.center[2]])
        carried = _Carried(tcp, pivot, box.corners() - pivot)
        spots, where, limits = request.spots, request.where, (request.spacing, request.budget, request.retreat)
        leaning: _Search | None = None
        best = None
        levelling = _levelling(tcp) if request.retreat[2] <= 0.5 else ()
        if levelling:
            # Into a compartment, a hand pitched down (a low object held from the side, tilted so that the hand
            # clears the table) lets go at a slant and backs out along it, the fingers sweeping up through where
            # the object lies (a lime hooked out of the cupboard): levelled first, most level first, where a
            # planner run reaches it (one that does not may be walled in, and the pitched hand's is not).
            leaning = self._search(carried, spots, PLACE_IK_QUICK, levelling[::-1], *limits)
            best = leaning.leaving if leaning.connected else None
        upright = _Search() if best is not None else self._search(carried, spots, PLACE_IK_QUICK, (0.0,), *limits)
        if best is None and leaning is not None:
            connected = upright.leaving if upright.connected else None
            best = connected or leaning.leaving or upright.leaving or upright.longest
        elif best is None:
            best = upright.leaving
            if best is None and request.retreat[2] > 0.5:
                # A pose the hand cannot back out of straight up would leave a program's own approach from above
                # (or its retreat) no room: leaning out from under what stands over the spot is better.
                leaning = self._search(carried, spots, PLACE_IK_QUICK, PLACE_LEANS, *limits)
                best = leaning.leaving or upright.longest
        if best is None:
            # The quick screen may miss the one IK branch that clears the furniture (a mug going into a drawer
            # pulled 20 cm, at the edge of the Panda's reach): the spots are searched again, widely.
            best = self._search(carried, spots, PLACE_IK_WIDE, (0.0,), *limits).longest
        if best is None and leaning is not None:
            best = leaning.longest
        if best is None:
            raise PlacementError(
                f"no reachable, collision-free pose puts {name!r} {where} ({upright.tried} spots tried): "
                f"{upright.errors[0] if upright.errors else 'no spot'}"
            )
        # Into a compartment, the hand goes in along its way out (the retreat's line, checked clear above).
        way_out = request.retreat * PLACE_RETREAT if request.retreat[2] < 0.5 else None
        self.motion.preferences.prefer(best[0], best[1], way_out)
        return best[0], best[2]

    def place_pose(self, name: str, receptacle: str | None, target: np.ndarray | None, tcp: Transform) -> Transform:
        """The gripper pose, from the hand at ``tcp``, that sets the held ``name`` down in or on ``receptacle``, at
        ``target`` or both (:meth:`PlaceRequests.spots`, :meth:`reachable`); a notice says where a position was
        moved to."""
        request = self.requests.spots(name, receptacle, target, tcp, self.taken_from(name))
        pose, spot = self.reachable(name, tcp, request)
        if request.target is not None and distance_moved(spot, request.target) > MOVED:
            why = (
                f"within {NEAR_BASE * 100:.0f} cm of the robot's base"
                if near_base(request.target, self.base_xy)
                else "taken, out of reach or off its support"
            )
            moved = distance_moved(spot, request.target) * 100
            notice(
                f"parse_place_pose: {np.round(request.target[:2], 3).tolist()} is {why}; putting {name!r} "
                f"{moved:.1f} cm away, at {np.round(spot.center[:2], 3).tolist()}"
            )
        return pose

    def raised_for_release(self, target: Transform, error: IKError, held: Collection[str]) -> Transform | None:
        """Where the TCP reaches ``target`` but only what it holds collides (an object that turned or slid down
        in the fingers since its place pose was made, now pressed into its support), the same pose raised the
        least that clears it, within :data:`PLACE_RAISE_LIMIT`; else None."""
        held = set(held)
        if not held or not error.colliding or error.position_error > 1e-3:
            return None
        # The pairs are those of every IK branch tried: other branches may put a link against the cabinet, so
        # what the hand holds need only be among them; the raised pose is checked in full.
        if not any(a in held or b in held for a, b in error.colliding):
            return None
        for lift in np.arange(0.01, PLACE_RAISE_LIMIT + 1e-9, 0.01):
            raised = Transform(target.position + np.array([0.0, 0.0, lift]), target.quaternion)
            try:
                self.motion.ik(raised)
            except IKError:
                continue
            return raised
        return None

    def _search(
        self,
        carried: _Carried,
        spots: list[PlacementSpot],
        search: IKSearch,
        leans: tuple[float, ...],
        spacing: float = REPEAT_SPACING,
        budget: int = PLACE_IK_BUDGET,
        retreat: np.ndarray = UP,
    ) -> _Search:
        """Spots in order (skipping near-repeats), for a collision-free IK from which the hand can also retreat
        straight up (:data:`PLACE_RETREAT`; along ``retreat``), as a place's retreat would: a hand put down with a
        link against the cabinet has no way out but through what it let go. Each spot is tried with the object
        turned as the spot allows (round, or any quarter turn at a position), and released higher up so the hand
        clears a deep container's walls, but first low (:data:`PLACE_LOW_LIFTS`) on the first
        :data:`PLACE_LOW_SPOTS` within :data:`PLACE_LOW_RADIUS` of the first one; ``leans``: the angles (degrees)
        the hand may lean toward the spot's open side, in order, at each height. Of the turns and IK branches that
        work at a height, the one nearest the arm's present configuration is taken (a hand kept facing one way can
        make the arm swing round behind itself), provided one planner run finds a path to it
        (:data:`PLACE_PATH_SCREENS` runs at most). The wide ``search`` (:data:`PLACE_IK_WIDE`) is a last resort and
        stops at the first spot it reaches."""
        q = self.motion.sync()
        found = _Search()
        distinct = _distinct(spots, spacing)
        tried: set[tuple[float, ...]] = set()
        # A short drop on one of the first few spots beats a long one on the first: a cup let go 5 cm above a plate
        # (the hand's first spot walled in lower down by the arm's own links) caught on the opening fingers.
        # Not far off, though: beyond a few centimetres the packing order counts for more (a gelatin box put 6 cm
        # into a basket's middle left no room for the last cup).
        # The spots beside the first are told apart more finely than repeats are: on a plate's round middle all
        # the spots a cup fits lie within a few centimetres of each other.
        beside = [s for s in _distinct(spots, PLACE_LOW_SPACING) if _apart(s, spots[0]) <= PLACE_LOW_RADIUS]
        for candidates, lifts in ((beside[:PLACE_LOW_SPOTS], PLACE_LOW_LIFTS), (distinct, PLACE_LIFTS)):
            for index, spot in enumerate(candidates):
                found.tried = max(found.tried, index + 1)
                for lift, lean in [(lift, lean) for lift in lifts for lean in leans]:
                    if budget <= 0:
                        return found
                    key = (*np.round(spot.center, 4), round(spot.yaw, 4), lift, lean)
                    if key in tried:
                        continue
                    tried.add(key)
                    budget -= len(spot.turns)
                    if self._try(found, carried, spot, (lift, lean), q, search, retreat):
                        return found
        return found

    def _try(
        self,
        found: _Search,
        carried: _Carried,
        spot: PlacementSpot,
        lift_lean: tuple[float, float],
        q: np.ndarray,
        search: IKSearch,
        retreat: np.ndarray,
    ) -> bool:
        """One spot at one height and lean (see :meth:`_search`), what it reaches added to ``found``; whether the
        search is over."""
        reached = self._place_options(carried, spot, *lift_lean, q, found.errors, search)
        options = [(self._retreat_room(pose, g, retreat), pose, g) for pose, goals in reached for g in goals]
        for room, pose, g in options:
            if found.longest is None or room > found.room + 1e-3:
                found.room, found.longest = room, (pose, g, spot)
        if search == PLACE_IK_WIDE:
            return bool(options)
        leaving = [(pose, g, spot) for room, pose, g in options if room >= PLACE_RETREAT - 1e-3]
        leaving.sort(key=lambda c: float(np.sum((c[1] - q) ** 2)))
        for pose, goal, _ in leaving[: found.screens]:
            found.screens -= 1
            # As a grasp's pre-grasp is screened: a configuration IK reaches may be walled in (a UR5e branch turned
            # back over its shoulder beside the basket), and no path reaches it.
            if self.motion.connects(q, goal):
                found.leaving, found.connected = (pose, goal, spot), True
                return True
        # Leaving the full retreat though no path was found to it in one planner run: the motion's own retries may
        # find one.
        found.leaving = found.leaving or (leaving[0] if leaving else None)
        return bool(leaving) and found.screens <= 0

    def _place_options(
        self,
        carried: _Carried,
        spot: PlacementSpot,
        lift: float,
        lean: float,
        q: np.ndarray,
        errors: list[str],
        search: IKSearch,
    ) -> list[tuple[Transform, list[np.ndarray]]]:
        """The gripper poses that put the held object at ``spot`` (``lift`` higher, leaning ``lean`` degrees
        toward the spot's open side), one per turn it allows, with their collision-free IK branches; the poses
        without any add their reason to ``errors``."""
        out = []
        tilt = self._lean_rotation(spot, lean)
        for turn in spot.turns:
            rotation = tilt @ quat_to_matrix(quat_from_yaw(spot.yaw + turn))
            # Turning the held object about its middle turns the gripper with it; a leaning object is raised so
            # that its lowest corner is as high above the support as an upright one's base would be.
            raised = np.array([0.0, 0.0, lift + carried.sink(rotation)])
            position = spot.center + raised + rotation @ (carried.tcp.position - carried.pivot)
            pose = Transform.from_rotation(position, rotation @ carried.tcp.rotation)
            try:
                out.append((pose, self.motion.ik_choices(pose, q, search)))
            except IKError as exc:
                errors.append(str(exc))
        return out

    def _lean_rotation(self, spot: PlacementSpot, lean: float) -> np.ndarray:
        """The rotation that tips the top of the hand ``lean`` degrees toward the spot's open side (toward the
        robot where the spot names none)."""
        if lean == 0.0:
            return np.eye(3)
        side = spot.open_side if spot.open_side is not None else np.append(self.base_xy - spot.center[:2], 0.0)
        side = np.array([side[0], side[1], 0.0]) / max(float(np.linalg.norm(side[:2])), 1e-9)
        # Rotating about (z x side) carries the vertical toward ``side``: the hand's top leans that way.
        return quat_to_matrix(quat_from_axis_angle(np.cross([0.0, 0.0, 1.0], side), math.radians(lean)))

    def _retreat_room(self, pose: Transform, q: np.ndarray, direction: np.ndarray = UP) -> float:
        """How far, up to :data:`PLACE_RETREAT`, the arm at ``q`` (the TCP at ``pose``) can move straight up (along
        ``direction``) after letting go there, the fingers opened fully without touching anything but what they
        held (what it held stays behind); 0 where the fingers cannot open."""
        up = Transform(pose.position + np.asarray(direction) * PLACE_RETREAT, pose.quaternion)
        scene = self.motion.scene
        with ignoring_held(scene), fingers_open(scene):
            return cartesian_path(self.motion.kinematics, scene, q, [up]).fraction * PLACE_RETREAT


def _levelling(tcp: Transform) -> tuple[float, ...]:
    """The leans (degrees, toward the front of a compartment) that level the hand at ``tcp``, pitched down, by
    :data:`PLACE_LEANS` and at most all the way; none for a hand about level."""
    pitch = math.degrees(math.asin(float(np.clip(-tcp.rotation[2, 2], -1.0, 1.0))))
    if pitch < LEVEL_PITCH:
        return ()
    return tuple(sorted({min(lean, pitch) for lean in (*PLACE_LEANS, pitch)}))


def _distinct(spots: list[PlacementSpot], spacing: float) -> list[PlacementSpot]:
    """The spots in order, without those within ``spacing`` of an earlier one turned the same way: a spot that
    near one that failed would fail the same way."""
    out: list[PlacementSpot] = []
    centres, yaws = np.empty((len(spots), 3)), np.empty(len(spots))
    for spot in spots:
        kept = len(out)
        near = np.linalg.norm(centres[:kept] - spot.center, axis=1) < spacing
        if not near.any() or not any(_same_turn(spot.yaw, float(yaw)) for yaw in yaws[:kept][near]):
            centres[kept], yaws[kept] = spot.center, spot.yaw
            out.append(spot)
    return out


def _apart(a: PlacementSpot, b: PlacementSpot) -> float:
    return float(np.linalg.norm(a.center[:2] - b.center[:2]))


def _same_turn(a: float, b: float) -> bool:
    """Whether two yaw turns face the same way, or opposite ways (a spot tried both ways round already)."""
    return abs(math.remainder(a - b, math.pi)) < 0.1
