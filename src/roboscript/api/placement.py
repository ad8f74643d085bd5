"""Placement search: the gripper pose that puts a held object into a receptacle, aside on the table, or at a
position, reachable and with room for the hand to let go and back away.

Spots come from :mod:`roboscript.api.spots` (geometry); this module asks perception what is where and the motion
planner what the arm can reach.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Collection

import numpy as np

from roboscript.api import compartments, supports
from roboscript.api.nearby import MOVED, NEAREST_BOUND, REPORT_BOUND, distance_moved, free_spots, ring_candidates
from roboscript.api.spots import (
    MARGIN,
    Footprint,
    PlacementSpot,
    fits,
    spots_in_receptacle,
)
from roboscript.errors import FailureError
from roboscript.geometry import Box3D, Transform, quat_from_axis_angle, quat_from_yaw, quat_to_matrix
from roboscript.names import TABLE, kind_of
from roboscript.notices import notice
from roboscript.perception.base import Perception, Receptacle
from roboscript.planning.cartesian import cartesian_path
from roboscript.planning.errors import IKError
from roboscript.planning.motion import MotionPlanner

DRAWER_WALL_MARGIN = 0.025
PLACE_PATH_SCREENS = 3  # planner runs per parse_place_pose call that check a place configuration can be reached
PLACE_IK_QUICK = (8, 24)  # IK attempts (wanted, at most) per place pose screened
PLACE_IK_WIDE = (24, 200)  # the same where the quick screen reached no spot
PLACE_IK_BUDGET = 96  # IK screens per parse_place_pose call (each costs a few milliseconds to ~0.1 s)
PLACE_IK_BUDGET_NEAR = 200  # the same round a program's position, whose spots are tried one ring after another
PLACE_RAISE_LIMIT = 0.04  # metres a place pose is raised at most when the held object has sunk in the hand
# How much higher than resting a held object is tried, lowest first: a longer drop topples tall things.
PLACE_LIFTS = (0.0, 0.01, 0.02, 0.05, 0.1)
PLACE_RETREAT = 0.10  # metres a place pose should leave straight above it: the customary pre-place approach and retreat
# Where no upright pose reaches any spot (a drawer beneath another, at the edge of the arm's reach), the hand leans
# this far (degrees) toward the spot's open side, the held object with it, and lets go of it there: an object
# released a few degrees off upright lands on its lower edge and settles back onto its base.
PLACE_LEANS = (20.0, 35.0)
LEVEL_PITCH = 5.0  # degrees below level under which a hand counts as level
# Where things may be put down on the table, from the robot's base: in front of it, clear of it, within reach.
TABLE_REACH = (np.array([0.15, -0.45]), np.array([0.73, 0.45]))
ASIDE_CLEARANCE = 0.035  # metres kept around a thing put aside on the table, for the fingers that come for it again
REPEAT_SPACING = 0.05  # metres: a receptacle's spot this near one that failed is not tried
NEAR_SPACING = 0.015  # the same round a program's position: a spot 2 cm further in may be the one within reach
# Nearer than this to the base, the Panda lifting a thing straight up from a grasp from above meets its joint limits.
ASIDE_MIN_REACH = 0.3
UP = np.array([0.0, 0.0, 1.0])


class PlacementError(FailureError, RuntimeError):
    """No free, reachable spot was found; the message says what was in the way."""


class ReceptacleFullError(PlacementError):
    """The receptacle has no free spot large enough for the object."""


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


@dataclasses.dataclass(frozen=True)
class PlaceRequest:
    """Where a held object may go, best first; the words that say where, for errors; the position a program
    asked for (None: a receptacle's spots); and how near a spot may be to one that failed and still be tried."""

    spots: list[PlacementSpot]
    where: str
    target: np.ndarray | None = None
    spacing: float = REPEAT_SPACING
    budget: int = PLACE_IK_BUDGET  # IK screens for the search
    # Which way the hand backs out after letting go: up, or out of the front of a compartment behind a door.
    retreat: np.ndarray = dataclasses.field(default_factory=lambda: UP.copy())


class Placer:
    """Placement search for the arm whose base stands at ``base_xy``."""

    def __init__(self, perception: Perception, motion: MotionPlanner, base_xy: np.ndarray):
        self.perception = perception
        self.motion = motion
        self.base_xy = np.asarray(base_xy, dtype=float)

    def spots(
        self, name: str, receptacle_name: str | None, position: np.ndarray | None, tcp: Transform
    ) -> PlaceRequest:
        """Where the held ``name`` (the hand at ``tcp``) could go: free spots in or on ``receptacle_name``
        (``'table'``: aside on the table; a door: the compartment behind it), or the nearest free ones to
        ``position`` (on that receptacle where one is named, else on whatever is under it), nearest first; with
        the words that say where, for errors."""
        if position is not None:
            target = np.asarray(position, dtype=float)
            on = "" if receptacle_name is None else f" on {receptacle_name!r}"
            where = f"at {np.round(target, 3).tolist()}{on} or within {NEAREST_BOUND * 100:.0f} cm of it"
            spots = self._spots_near(name, receptacle_name, target)
            return PlaceRequest(spots, where, target, NEAR_SPACING, PLACE_IK_BUDGET_NEAR)
        others = [o for o in self.perception.objects() if o not in (name, receptacle_name)]
        receptacle = self._receptacle(receptacle_name, name)
        if kind_of(receptacle.name) == "door":
            return self._compartment_request(name, receptacle, others, tcp)
        if receptacle_name == TABLE:
            spots = self._spots_aside(name, receptacle, others)
        elif self.perception.receptacle(receptacle.name) is None:
            spots = self._spots_on_top(name, receptacle)
        else:
            spots = self._spots_in(name, receptacle, others)
            surface = supports.whole_surface(self.perception, receptacle)
            if not spots and surface is not None:
                spots = self._spots_in(name, surface, others)
        if not spots:
            inside = [o for o in others if _within(self.perception.box(o), receptacle)]
            size = self.perception.box(name).size
            raise ReceptacleFullError(
                f"{receptacle_name!r} has no free spot for {name!r} "
                f"({size[0] * 100:.0f} x {size[1] * 100:.0f} cm); "
                f"it holds {', '.join(inside) or 'nothing'}"
            )
        return PlaceRequest(spots, f"in {receptacle_name!r}")

    def _compartment_request(
        self, name: str, receptacle: Receptacle, others: list[str], tcp: Transform
    ) -> PlaceRequest:
        """Spots in the compartment behind a door, for the hand at ``tcp`` turned to point into it; the hand
        backs out of the front after letting go."""
        turn = compartments.hand_turn(tcp, receptacle, name)
        inside = [o for o in others if _within(self.perception.box(o), receptacle)]
        size = self.perception.box(name).size
        spots = compartments.compartment_spots(
            receptacle, self._footprint(name), size[2], turn, [self._footprint(o) for o in inside], self.base_xy
        )
        if not spots:
            raise ReceptacleFullError(
                f"{receptacle.name!r} has no free spot for {name!r} ({size[0] * 100:.0f} x {size[1] * 100:.0f} x "
                f"{size[2] * 100:.0f} cm); it holds {', '.join(inside) or 'nothing'}"
            )
        return PlaceRequest(spots, f"in {receptacle.name!r}", retreat=compartments.open_side(receptacle))

    def _spots_near(self, name: str, receptacle_name: str | None, target: np.ndarray) -> list[PlacementSpot]:
        """Free spots for the held ``name`` at ``target`` or round it within :data:`NEAREST_BOUND`, nearest
        first; a PlacementError that says how far the nearest free one is where there is none."""
        _, yaw, half = self.perception.footprint(name)
        height = self.perception.box(name).size[2]
        if receptacle_name is None:
            support = supports.support_under(self.perception, name, target[:2], np.asarray(half))
        else:
            # On the table at a position: anywhere on its top (reach is for the motion planner to judge), not only
            # where things are put aside.
            named = supports.table_top(self.perception) if receptacle_name == TABLE else None
            support = supports.support_named(self.perception, name, named or self._receptacle(receptacle_name, name))
        spots = free_spots(ring_candidates(target[:2], NEAREST_BOUND, self.base_xy), half, yaw, height, support)
        spots = _open_side(spots, support.region)
        if spots:
            return spots
        farther = free_spots(ring_candidates(target[:2], REPORT_BOUND, self.base_xy), half, yaw, height, support)
        where = f"on {support.region.name!r}"
        nearest = (
            f"the nearest free spot {where} is {distance_moved(farther[0], target) * 100:.0f} cm away, at "
            f"{np.round(farther[0].center[:2], 3).tolist()}"
            if farther
            else f"no spot {where} within {REPORT_BOUND * 100:.0f} cm is free"
        )
        raise PlacementError(
            f"{np.round(target[:2], 3).tolist()} has no room for {name!r} within {NEAREST_BOUND * 100:.0f} cm "
            f"(something stands there, or it is off {support.region.name!r}): {nearest}"
        )

    def _spots_on_top(self, name: str, top: Receptacle) -> list[PlacementSpot]:
        """Spots on an object's flat top (stacking): its middle first, the held object squared to it."""
        _, yaw, half = self.perception.footprint(name)
        height = self.perception.box(name).size[2]
        support = supports.support_named(self.perception, name, top)
        middle = top.frame.position[:2]
        frame_yaw = math.atan2(top.frame.rotation[1, 0], top.frame.rotation[0, 0])
        spots = free_spots(ring_candidates(middle, 0.02, self.base_xy), half, yaw, height, support)
        # Squared to the top it stands on: turned by the difference of yaws (any quarter turn).
        square = math.remainder(frame_yaw - yaw, math.pi / 2)
        return [dataclasses.replace(s, yaw=square) for s in spots]

    def reachable(self, name: str, tcp: Transform, request: PlaceRequest) -> tuple[Transform, PlacementSpot]:
        """The gripper pose, from the hand at ``tcp`` holding ``name``, for the first of ``spots`` the arm can
        reach and leave; the configuration chosen becomes the motion's goal for that pose
        (:meth:`MotionPlanner.prefer_goal`).

        In order of preference: an upright pose that leaves the full retreat (:data:`PLACE_RETREAT`) and that
        one planner run reaches (see :meth:`_search`), or failing a path, one that leaves the retreat; the same
        with the hand leaning toward the spot's open side (:data:`PLACE_LEANS`); an upright pose that leaves the
        longest retreat; an upright pose found by a wider IK search; a leaning pose that leaves the longest
        retreat."""
        # Spots are where the middle of the object's footprint goes (for a curved banana lying turned, not the
        # middle of its world-aligned box): the hand turns about that.
        footprint_center = self.perception.footprint(name)[0]
        box = self.perception.box(name)
        pivot = np.array([footprint_center[0], footprint_center[1], box.center[2]])
        carried = _Carried(tcp, pivot, box.corners() - pivot)
        spots, where, limits = request.spots, request.where, (request.spacing, request.budget, request.retreat)
        upright = self._search(carried, spots, PLACE_IK_QUICK, (0.0,), *limits)
        best = upright.leaving
        leaning: _Search | None = None
        leans = PLACE_LEANS if request.retreat[2] > 0.5 else _levelling(tcp)
        if best is None and leans:
            # A pose the hand cannot back out of straight up would leave a program's own approach from above
            # (or its retreat) no room: leaning out from under what stands over the spot is better. A hand
            # pitched down into a compartment (a low object held from the side, tilted so that the hand clears
            # the table) brings the wrist up against the panel above: levelled, it tilts the object instead.
            leaning = self._search(carried, spots, PLACE_IK_QUICK, leans, *limits)
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
        self.motion.prefer_goal(best[0], best[1])
        return best[0], best[2]

    def place_pose(self, name: str, receptacle: str | None, target: np.ndarray | None, tcp: Transform) -> Transform:
        """The gripper pose, from the hand at ``tcp``, that sets the held ``name`` down in or on ``receptacle``, at
        ``target`` or both (:meth:`spots`, :meth:`reachable`); a notice says where a position was moved to."""
        request = self.spots(name, receptacle, target, tcp)
        pose, spot = self.reachable(name, tcp, request)
        if request.target is not None and distance_moved(spot, request.target) > MOVED:
            notice(
                f"parse_place_pose: {np.round(request.target[:2], 3).tolist()} is taken, out of reach or off its "
                f"support; putting {name!r} {distance_moved(spot, request.target) * 100:.1f} cm away, at "
                f"{np.round(spot.center[:2], 3).tolist()}"
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

    def _spots_aside(self, name: str, table: Receptacle, others: list[str]) -> list[PlacementSpot]:
        """Spots on the table for putting the held object aside: clear of objects, furniture and whatever the
        cameras see there, near where it was but not on it."""
        box = self.perception.box(name)
        _, yaw, half = self.perception.footprint(name)
        obstacles = [self._footprint(o) for o in others]
        obstacles += [Footprint.of_box(self.perception.box(n)) for n in self.perception.furniture()]
        # A thing put aside is usually picked up again (a swap): spots that leave a hand room to come for it
        # between its neighbours, and the arm room to lift it (not folded against its own base), come first; the
        # merely free ones only where there are none.
        occupied = self.perception.occupied([name])
        for clearance, reach in ((ASIDE_CLEARANCE, ASIDE_MIN_REACH), (0.0, ASIDE_MIN_REACH), (0.0, 0.0)):
            grown = [Footprint(o.center, o.yaw, o.half + clearance) for o in obstacles]
            spots = spots_in_receptacle(table, half, yaw, box.size[2], grown, self.base_xy, near_xy=box.center[:2])
            radius = float(np.linalg.norm(half)) + MARGIN + clearance
            spots = _clear_of(spots, occupied, radius, table.lower[2])
            spots = [
                s
                for s in spots
                if np.linalg.norm(s.center[:2] - box.center[:2]) > 0.15
                and np.linalg.norm(s.center[:2] - self.base_xy) >= reach
            ]
            if spots:
                return spots
        return []

    def _spots_in(self, name: str, receptacle: Receptacle, others: list[str]) -> list[PlacementSpot]:
        """Free spots for the held object in a container or a drawer, clear of what is already in it."""
        _, yaw, half = self.perception.footprint(name)
        inside = [self._footprint(o) for o in others if _within(self.perception.box(o), receptacle)]
        drawer = kind_of(receptacle.name) == "drawer"
        # A drawer's front and walls stand high around a held object that may swing a little.
        wall_margin = DRAWER_WALL_MARGIN if drawer else MARGIN
        height = self.perception.box(name).size[2]
        corner = self._fill_corner(receptacle)
        spots = spots_in_receptacle(receptacle, half, yaw, height, inside, corner, wall_margin=wall_margin)
        return _open_side(spots, receptacle)

    def _receptacle(self, receptacle_name: str, held: str) -> Receptacle:
        """What ``receptacle_name`` holds things in or on: its interior, or its flat top (stacking)."""
        if receptacle_name == TABLE:
            return self._table_region()
        name = self.perception.require(receptacle_name)
        if name == held:
            raise ValueError(f"cannot place {held!r} into itself")
        receptacle = supports.holds(self.perception, name)
        if receptacle is None:
            holding = [n for n in self.perception.names() if n != held and supports.holds(self.perception, n)]
            raise ValueError(
                f"{name!r} cannot hold things: it has no interior and no flat top; receptacles here: "
                f"{', '.join([*holding, TABLE])}; or pass position=[x, y, z]"
            )
        if supports.is_closed(self.perception, receptacle):
            raise PlacementError(f"{name!r} is closed: open it before placing anything into it")
        _, _, half = self.perception.footprint(held)
        if self.perception.receptacle(name) is not None and not fits(receptacle, half):
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

    def _fill_corner(self, receptacle: Receptacle) -> np.ndarray:
        """Where filling starts: the corner nearest the robot; for a drawer, the front corner nearest the robot
        (the back of an open drawer is under the carcass, where the arm has no room)."""
        if kind_of(receptacle.name) != "drawer":
            return self.base_xy
        lower, upper = receptacle.lower, receptacle.upper
        fronts = receptacle.frame.apply(np.array([[upper[0], lower[1], 0.0], [upper[0], upper[1], 0.0]]))[:, :2]
        return fronts[int(np.argmin(np.linalg.norm(fronts - self.base_xy, axis=1)))]

    def _search(
        self,
        carried: _Carried,
        spots: list[PlacementSpot],
        search: tuple[int, int],
        leans: tuple[float, ...],
        spacing: float = REPEAT_SPACING,
        budget: int = PLACE_IK_BUDGET,
        retreat: np.ndarray = UP,
    ) -> _Search:
        """Spots in order (skipping near-repeats of spots that failed), for a collision-free IK from which the hand can
        also retreat straight up (:data:`PLACE_RETREAT`; along ``retreat``), as a place's retreat would: a hand put down
        with a link against the cabinet has no way out but through what it let go. Each spot is tried with the object
        turned as the spot allows (round, or any quarter turn at a position), and released higher up so the hand clears
        a deep container's walls; ``leans``: the angles (degrees) the hand may lean toward the spot's open side, in
        order, at each height. Of the turns and IK branches that work at a height, the one nearest the arm's present
        configuration is taken (a hand kept facing one way can make the arm swing round behind itself), provided one
        planner run finds a path to it (:data:`PLACE_PATH_SCREENS` runs at most). The wide ``search``
        (:data:`PLACE_IK_WIDE`) is a last resort and stops at the first spot it reaches."""
        q = self.motion.sync()
        found = _Search()
        tried: list[PlacementSpot] = []
        screens = PLACE_PATH_SCREENS
        done = False
        for spot in spots:
            if budget <= 0 or done:
                break
            if any(np.linalg.norm(spot.center - t.center) < spacing and _same_turn(spot.yaw, t.yaw) for t in tried):
                continue
            tried.append(spot)
            found.tried += 1
            for lift, lean in [(lift, lean) for lift in PLACE_LIFTS for lean in leans]:
                reached = self._place_options(carried, spot, lift, lean, q, found.errors, search)
                budget -= len(spot.turns)
                options = [(self._retreat_room(pose, g, retreat), pose, g) for pose, goals in reached for g in goals]
                for room, pose, g in options:
                    if found.longest is None or room > found.room + 1e-3:
                        found.room, found.longest = room, (pose, g, spot)
                if search == PLACE_IK_WIDE:
                    done = bool(options)
                else:
                    leaving = [(pose, g, spot) for room, pose, g in options if room >= PLACE_RETREAT - 1e-3]
                    leaving.sort(key=lambda c: float(np.sum((c[1] - q) ** 2)))
                    for pose, goal, _ in leaving[:screens]:
                        screens -= 1
                        # As a grasp's pre-grasp is screened: a configuration IK reaches may be walled in (a UR5e
                        # branch turned back over its shoulder beside the basket), and no path reaches it.
                        if self.motion.connects(q, goal):
                            found.leaving = (pose, goal, spot)
                            return found
                    # Leaving the full retreat though no path was found to it in one planner run: the motion's
                    # own retries may find one.
                    found.leaving = found.leaving or (leaving[0] if leaving else None)
                    done = bool(leaving) and screens <= 0
                if done or budget <= 0:
                    break
        return found

    def _place_options(
        self,
        carried: _Carried,
        spot: PlacementSpot,
        lift: float,
        lean: float,
        q: np.ndarray,
        errors: list[str],
        search: tuple[int, int],
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
                out.append((pose, self.motion.ik_choices(pose, q, attempts=search[0], max_attempts=search[1])))
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
        with scene.ignoring_held(), scene.fingers_open():
            return cartesian_path(self.motion.kinematics, scene, q, [up]).fraction * PLACE_RETREAT


def _levelling(tcp: Transform) -> tuple[float, ...]:
    """The leans (degrees, toward the front of a compartment) that level the hand at ``tcp``, pitched down, by
    :data:`PLACE_LEANS` and at most all the way; none for a hand about level."""
    pitch = math.degrees(math.asin(float(np.clip(-tcp.rotation[2, 2], -1.0, 1.0))))
    if pitch < LEVEL_PITCH:
        return ()
    return tuple(sorted({min(lean, pitch) for lean in (*PLACE_LEANS, pitch)}))


def _clear_of(spots: list, points: np.ndarray, radius: float, table_top: float) -> list:
    """The spots with no observed point above the table within ``radius`` of their centre (on the table's level:
    the table itself and what hangs high above it do not count)."""
    band = points[(points[:, 2] > table_top + 0.005) & (points[:, 2] < table_top + 0.5)][:, :2]
    if len(band) == 0:
        return spots
    # Points binned in cells as wide as the radius: only the 3x3 cells round a spot's can be that near it.
    cells: dict[tuple[int, int], list[int]] = {}
    for index, cell in enumerate(map(tuple, np.floor(band / radius).astype(int).tolist())):
        cells.setdefault(cell, []).append(index)
    kept = []
    for s in spots:
        cx, cy = (int(v) for v in np.floor(s.center[:2] / radius))
        near = [i for dx in (-1, 0, 1) for dy in (-1, 0, 1) for i in cells.get((cx + dx, cy + dy), ())]
        if not near or float(np.min(np.linalg.norm(band[near] - s.center[:2], axis=1))) > radius:
            kept.append(s)
    return kept


def _open_side(spots: list[PlacementSpot], receptacle: Receptacle) -> list[PlacementSpot]:
    """The spots, in a drawer with its open side: open, a drawer is clear above only on its pulled-out side (its
    front faces its frame's +x)."""
    if kind_of(receptacle.name) != "drawer":
        return spots
    out = receptacle.frame.rotation[:, 0]
    return [dataclasses.replace(s, open_side=out) for s in spots]


def _same_turn(a: float, b: float) -> bool:
    """Whether two yaw turns face the same way, or opposite ways (a spot tried both ways round already)."""
    return abs(math.remainder(a - b, math.pi)) < 0.1


def _within(box: Box3D, receptacle: Receptacle) -> bool:
    """Whether an object's box centre lies in the receptacle's interior (in its frame)."""
    local = receptacle.frame.inverse().apply(box.center[None])[0]
    return bool(np.all(local >= receptacle.lower - 0.01) and np.all(local <= receptacle.upper + 0.01))
