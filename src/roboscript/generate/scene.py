"""What a world offers template tasks: the things on the table, the receptacles and what fits into each, the
cabinet's drawers, colours and kinds. Geometry only, from the world file (no simulation)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from roboscript.names import kind_of
from roboscript.objects import ObjectType
from roboscript.sim.world_file import ObjectPlacement, WorldSpec

# What an instruction calls each kind of thing sorting by kind speaks of (the kinds of ``objects/reading.yaml``).
KINDS: dict[str, str] = {
    "fruit": "fruits",
    "ball": "balls",
    "block": "blocks",
    "box": "boxes",
    "toy": "toy vehicles",
    "drinkware": "cups and mugs",
    "bottle": "bottles and cans",
}
DRAWER_HEIGHT_LIMIT = 0.1  # taller things stand out of a drawer (the object-shape study: 50-79% inside)
DRAWERS_USED = 2  # the top two: the lower ones are low for a hand coming from above
# A hand gripping a drawer's bar from the front closes its fingers up and down, the hand 21 cm across that way (the
# Panda's): a handle lower than this above the table leaves it no room.
HANDLE_ROOM = 0.15
# A compartment at least this tall has room for a level hand carrying a thing in through its door.
COMPARTMENT_HEIGHT = 0.18


def in_or_on(thing: ObjectType, receptacle: ObjectType) -> str:
    """The check that says ``thing`` was put into ``receptacle``: ``in`` (80% of its box inside the receptacle's)
    where it sinks deep enough for that, else ``on`` (resting over it): an apple in a shallow bowl, on a plate."""
    if receptacle.shape in ("flat",) or receptacle.interior is None:
        return "on"
    floor = receptacle.interior[0][2]
    depth = float(receptacle.bounds[1][2]) - floor
    # 2 cm to spare: a thing as wide as a Rubik's cube rests on a bowl's sloping walls, above its floor.
    return "in" if 0.8 * float(thing.size[2]) <= depth - 0.02 else "on"


def fits(thing: ObjectType, receptacle: ObjectType, margin: float = 0.01) -> bool:
    """Whether ``thing`` stands inside ``receptacle``'s interior with ``margin`` to spare on each side, in the
    worst turn (its diagonal)."""
    lower, upper = receptacle.interior
    inner = min(upper[0] - lower[0], upper[1] - lower[1])
    return math.hypot(*thing.size[:2]) + 2 * margin <= inner or bool(
        np.all(np.sort(thing.size[:2]) + 2 * margin + 0.02 <= np.sort(np.subtract(upper, lower)[:2]))
    )


def room_for(things: list[ObjectType], receptacle: ObjectType, held: list[ObjectType] | None = None) -> bool:
    """Whether all of ``things`` fit into ``receptacle`` side by side, each with a margin, at most half its floor
    covered (a pear and a peach fill a plate's 16 cm: the first one put down leaves no room for the second), beside
    what it ``held`` at the start (in its middle, as generated worlds put things in receptacles)."""
    held = held or []
    lower, upper = receptacle.interior
    floor = (upper[0] - lower[0]) * (upper[1] - lower[1])
    taken = sum((t.size[0] + 0.02) * (t.size[1] + 0.02) for t in [*held, *things])
    beside = all(_fits_beside(t, h, receptacle) for t in things for h in held)
    return all(fits(t, receptacle) for t in things) and taken <= 0.5 * floor and beside


def _fits_beside(thing: ObjectType, held: ObjectType, receptacle: ObjectType) -> bool:
    """Whether ``thing`` fits between ``held``, in any turn in the receptacle's middle, and a wall."""
    lower, upper = receptacle.interior
    short, long = np.sort(np.subtract(upper, lower)[:2])
    strip = (long - 2 * held.footprint_radius) / 2
    small, large = np.sort(thing.size[:2])
    return bool(small + 0.03 <= strip and large + 0.02 <= short)


@dataclass(frozen=True)
class Scene:
    """A world as template tasks see it."""

    world: WorldSpec

    @cached_property
    def placements(self) -> dict[str, ObjectPlacement]:
        return {o.name: o for o in self.world.objects}

    def type(self, name: str) -> ObjectType:
        return self.placements[name].type

    @cached_property
    def on_table(self) -> list[str]:
        """Pickable things standing on the table itself (not in or on a receptacle)."""
        return [o.name for o in self.world.objects if o.type.pickable and o.support_kind == "table"]

    @cached_property
    def receptacles(self) -> list[str]:
        """Plates, saucers, bowls and baskets (what tasks put things into or onto)."""
        return [o.name for o in self.world.objects if not o.type.pickable and o.type.interior is not None]

    @cached_property
    def containers(self) -> list[str]:
        """Receptacles with walls: bowls and baskets."""
        return [r for r in self.receptacles if self.type(r).shape != "flat"]

    @cached_property
    def plates(self) -> list[str]:
        """Flat receptacles: plates and saucers."""
        return [r for r in self.receptacles if self.type(r).shape == "flat"]

    def holding(self, receptacle: str) -> list[str]:
        """What starts in or on ``receptacle``."""
        return [o.name for o in self.world.objects if o.support == receptacle]

    @cached_property
    def drawers(self) -> list[str]:
        """The drawers tasks use: the top :data:`DRAWERS_USED` of those whose handle stands high enough for a hand
        gripping its bar from the front (:data:`HANDLE_ROOM`)."""
        drawers = [
            name
            for c in self.world.cabinets
            for (row, name), middle in zip(c.row_parts(), c.row_middles(), strict=True)
            if row.kind == "drawer" and middle >= HANDLE_ROOM
        ]
        return drawers[:DRAWERS_USED]

    @cached_property
    def doors(self) -> list[str]:
        return [p for p in self.world.part_names() if kind_of(p) == "door"]

    @cached_property
    def any_open(self) -> bool:
        """Whether the world starts with a drawer or door open."""
        return any(row.open for c in self.world.cabinets for row in c.rows)

    def opened(self, part: str) -> float:
        """How far a drawer (metres) or door (radians) starts open."""
        return next((row.open for c in self.world.cabinets for row, name in c.row_parts() if name == part), 0.0)

    @cached_property
    def compartments(self) -> list[str]:
        """The doors with a compartment behind them tall enough for a hand to put things in (see
        :data:`COMPARTMENT_HEIGHT`)."""
        return [
            name
            for c in self.world.cabinets
            for row, name in c.row_parts()
            if row.kind == "door" and row.height >= COMPARTMENT_HEIGHT
        ]

    def handle_of(self, drawer: str) -> str:
        """The handle of ``drawer``: handles are numbered by row, drawers among drawers."""
        cabinet = next(c for c in self.world.cabinets if drawer.startswith(f"{c.name}."))
        parts = cabinet.part_names()
        return parts[parts.index(drawer) + 1]

    def position(self, name: str) -> np.ndarray:
        return np.array(self.placements[name].position[:2])

    def radius(self, name: str) -> float:
        return self.type(name).footprint_radius
