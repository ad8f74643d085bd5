"""Where a held object may go: free spots in or on a receptacle (a container, a drawer, a box's flat top, the
compartment behind a door), aside on the table, or round a position a program gave, best first, with the words
that say where for errors.

Spots come from :mod:`roboscript.api.spots` (geometry) and this module asks perception what is where; which of them
the arm can reach is :mod:`roboscript.api.placement`'s question.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from scipy.spatial import cKDTree

from roboscript.api import compartments, supports
from roboscript.api.nearby import (
    NEAREST_BOUND,
    REPORT_BOUND,
    clear_of_base,
    distance_moved,
    free_spots,
    ranked,
    ring_candidates,
)
from roboscript.api.spots import MARGIN, Footprint, PlacementSpot, fits, spots_in_receptacle
from roboscript.errors import FailureError
from roboscript.geometry import Box3D, Transform
from roboscript.names import TABLE, kind_of
from roboscript.perception.base import Perception, Receptacle

DRAWER_WALL_MARGIN = 0.025
PLACE_IK_BUDGET = 96  # IK screens per parse_place_pose call (each costs a few milliseconds to ~0.1 s)
PLACE_IK_BUDGET_NEAR = 200  # the same round a program's position, whose spots are tried one ring after another
# Where things may be put down on the table, from the robot's base: in front of it, clear of it, within reach.
ASIDE_AWAY = 0.15  # metres at least from where it stood that a thing put aside goes (parse_place_pose says so)
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


class PlaceRequests:
    """Where things may go, for the arm whose base stands at ``base_xy``."""

    def __init__(self, perception: Perception, base_xy: np.ndarray):
        self.perception = perception
        self.base_xy = np.asarray(base_xy, dtype=float)

    def spots(
        self,
        name: str,
        receptacle_name: str | None,
        position: np.ndarray | None,
        tcp: Transform,
        origin: np.ndarray | None = None,
    ) -> PlaceRequest:
        """Where the held ``name`` (the hand at ``tcp``, having taken it at ``origin`` (x, y), where known) could
        go: free spots in or on ``receptacle_name`` (``'table'``: aside on the table; a door: the compartment
        behind it), or the nearest free ones to ``position`` (on that receptacle where one is named, else on
        whatever is under it), nearest first; with the words that say where, for errors."""
        others = [o for o in self.perception.objects() if o not in (name, receptacle_name)]
        if position is not None and receptacle_name is not None and kind_of(receptacle_name) == "door":
            return self._compartment_near(name, receptacle_name, others, np.asarray(position, dtype=float), tcp)
        if position is not None:
            target = np.asarray(position, dtype=float)
            on = "" if receptacle_name is None else f" on {receptacle_name!r}"
            where = f"at {np.round(target, 3).tolist()}{on} or within {NEAREST_BOUND * 100:.0f} cm of it"
            spots = self._spots_near(name, receptacle_name, target, origin)
            return PlaceRequest(spots, where, target, NEAR_SPACING, PLACE_IK_BUDGET_NEAR)
        receptacle = self._receptacle(receptacle_name, name)
        if kind_of(receptacle.name) == "door":
            return self._compartment_request(name, receptacle, others, tcp)
        if receptacle_name == TABLE:
            spots = self._spots_aside(name, receptacle, others, origin)
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

    def _compartment_near(
        self, name: str, door: str, others: list[str], target: np.ndarray, tcp: Transform
    ) -> PlaceRequest:
        """A position behind a door: the compartment's free spots nearest it (in x and y; the floor decides the
        height), within :data:`NEAREST_BOUND`. The hand goes in and backs out of the front as for the compartment
        itself: a position deep in it is no spot on a table to leave upward (the panel above is in the way)."""
        receptacle = self._receptacle(door, name)
        request = self._compartment_request(name, receptacle, others, tcp)
        spots = sorted(request.spots, key=lambda spot: distance_moved(spot, target))
        near = [spot for spot in spots if distance_moved(spot, target) <= NEAREST_BOUND]
        if not near:
            raise PlacementError(
                f"{np.round(target[:2], 3).tolist()} has no room for {name!r} within {NEAREST_BOUND * 100:.0f} cm "
                f"in {door!r}: the nearest free spot in it is {distance_moved(spots[0], target) * 100:.0f} cm away, "
                f"at {np.round(spots[0].center[:2], 3).tolist()}"
            )
        where = f"at {np.round(target, 3).tolist()} in {door!r} or within {NEAREST_BOUND * 100:.0f} cm of it"
        return PlaceRequest(near, where, target, NEAR_SPACING, PLACE_IK_BUDGET_NEAR, retreat=request.retreat)

    def _spots_near(
        self, name: str, receptacle_name: str | None, target: np.ndarray, origin: np.ndarray | None = None
    ) -> list[PlacementSpot]:
        """Free spots for the held ``name`` at ``target`` or round it within :data:`NEAREST_BOUND`, best first
        (:func:`ranked`; ``origin``: where it was taken); a PlacementError that says how far the nearest free one
        is where there is none."""
        yaw, half, outline = self._held_shape(name)
        height = self.perception.box(name).size[2]
        table = supports.table_top(self.perception)
        if receptacle_name is None:
            under = supports.support_under(self.perception, name, target[:2], np.asarray(half))
            # Nothing named: where the flat top under the position has no room (a temporary spot that fell on an
            # occupied saucer), the table round it; a full bowl or drawer is an error (it was meant to go in).
            candidates = [under]
            if under.region.name != TABLE and not supports.has_walls(self.perception, under.region):
                candidates.append(supports.support_named(self.perception, name, table))
        else:
            # On the table at a position: anywhere on its top (reach is for the motion planner to judge), not only
            # where things are put aside.
            named = table if receptacle_name == TABLE else self._receptacle(receptacle_name, name)
            candidates = [supports.support_named(self.perception, name, named)]
        ring = ring_candidates(target[:2], NEAREST_BOUND, self.base_xy)
        for support in candidates:
            spots = free_spots(ring, half, yaw, height, support, outline)
            spots = ranked(spots, target[:2], half, yaw, support.obstacles, origin, outline)
            spots = clear_of_base(spots, self.base_xy)
            spots = _open_side(spots, support.region)
            if spots:
                return spots
        support = candidates[-1]  # the widest search: where the nearest free spot is
        wider = ring_candidates(target[:2], REPORT_BOUND, self.base_xy)
        farther = free_spots(wider, half, yaw, height, support, outline)
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

    def _spots_aside(
        self, name: str, table: Receptacle, others: list[str], origin: np.ndarray | None = None
    ) -> list[PlacementSpot]:
        """Spots on the table for putting the held object aside: clear of objects, furniture and whatever the
        cameras see there, near where it was taken (``origin``; else where it is now) but not on it."""
        box = self.perception.box(name)
        where = box.center[:2] if origin is None else np.asarray(origin, dtype=float)
        _, yaw, half = self.perception.footprint(name)
        obstacles = [self._footprint(o) for o in others]
        obstacles += [Footprint.of_box(self.perception.box(n)) for n in self.perception.furniture()]
        # A thing put aside is usually picked up again (a swap): spots that leave a hand room to come for it
        # between its neighbours, and the arm room to lift it (not folded against its own base), come first; the
        # merely free ones only where there are none.
        occupied = self.perception.occupied([name])
        for clearance, reach in ((ASIDE_CLEARANCE, ASIDE_MIN_REACH), (0.0, ASIDE_MIN_REACH), (0.0, 0.0)):
            grown = [Footprint(o.center, o.yaw, o.half + clearance) for o in obstacles]
            spots = spots_in_receptacle(table, half, yaw, box.size[2], grown, self.base_xy, near_xy=where)
            radius = float(np.linalg.norm(half)) + MARGIN + clearance
            spots = _clear_of(spots, occupied, radius, table.lower[2])
            spots = [
                s
                for s in spots
                if np.linalg.norm(s.center[:2] - where) > ASIDE_AWAY
                and np.linalg.norm(s.center[:2] - self.base_xy) >= reach
            ]
            if spots:
                return spots
        return []

    def _spots_in(self, name: str, receptacle: Receptacle, others: list[str]) -> list[PlacementSpot]:
        """Free spots for the held object in a container or a drawer, clear of what is already in it."""
        yaw, half, outline = self._held_shape(name)
        inside = [self._footprint(o) for o in others if _within(self.perception.box(o), receptacle)]
        drawer = kind_of(receptacle.name) == "drawer"
        # A drawer's front and walls stand high around a held object that may swing a little.
        wall_margin = DRAWER_WALL_MARGIN if drawer else MARGIN
        height = self.perception.box(name).size[2]
        corner = self._fill_corner(receptacle)
        spots = spots_in_receptacle(
            receptacle, half, yaw, height, inside, corner, wall_margin=wall_margin, outline=outline
        )
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
        return supports.object_footprint(self.perception, name)

    def _held_shape(self, name: str) -> tuple[float, np.ndarray, np.ndarray]:
        """The held ``name``'s footprint's ``(yaw, half_extents_xy)`` and its outline from above, relative to the
        footprint's middle."""
        middle, yaw, half = self.perception.footprint(name)
        return yaw, half, self.perception.outline(name) - np.asarray(middle, dtype=float)

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


def _clear_of(spots: list, points: np.ndarray, radius: float, table_top: float) -> list:
    """The spots with no observed point above the table within ``radius`` of their centre (on the table's level:
    the table itself and what hangs high above it do not count)."""
    band = points[(points[:, 2] > table_top + 0.005) & (points[:, 2] < table_top + 0.5)][:, :2]
    if len(band) == 0 or not spots:
        return spots
    centres = np.array([s.center[:2] for s in spots])
    nearest, _ = cKDTree(band).query(centres, distance_upper_bound=radius)
    return [s for s, distance in zip(spots, nearest, strict=True) if distance > radius]


def _open_side(spots: list[PlacementSpot], receptacle: Receptacle) -> list[PlacementSpot]:
    """The spots, in a drawer with its open side: open, a drawer is clear above only on its pulled-out side (its
    front faces its frame's +x)."""
    if kind_of(receptacle.name) != "drawer":
        return spots
    out = receptacle.frame.rotation[:, 0]
    return [dataclasses.replace(s, open_side=out) for s in spots]


def _within(box: Box3D, receptacle: Receptacle) -> bool:
    """Whether an object's box centre lies in the receptacle's interior (in its frame)."""
    local = receptacle.frame.inverse().apply(box.center[None])[0]
    return bool(np.all(local >= receptacle.lower - 0.01) and np.all(local <= receptacle.upper + 0.01))
