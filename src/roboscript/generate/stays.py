"""What an instruction implies stays as it was: the "and nothing else" a reader hears in it.

"Put the red objects on the red plate" also says that the green block does not go there; "put the cup next to the
can" that the can stays where it is; "clear the table ... leave the bowls where they are" that the bowls stay. A
template task checks these too (the original benchmark's negated checks), so that a program that moves everything
cannot pass where a careful one does. Each check is made only where the words leave no doubt: a thing whose colour
or kind its name does not say is checked neither way, and so is a part that starts open.
"""

from __future__ import annotations

from collections.abc import Iterable

from roboscript.generate.scene import Scene, in_or_on
from roboscript.names import kind_of

# A thing that must stay may end this far from where it started: a hand passing by may nudge it, not move it.
STAY_WITHIN = 0.05
DRAWER_SHUT = 0.03  # metres a drawer may stay out and count as closed
DOOR_SHUT = 0.15  # radians (9 degrees) a door may stand ajar and count as closed


def stays_put(names: Iterable[str]) -> tuple[dict, ...]:
    """Each of ``names`` ends within :data:`STAY_WITHIN` of where it started."""
    return tuple({"at": name, "start_of": name, "within": STAY_WITHIN} for name in names)


def stays_out(scene: Scene, receptacle: str, names: Iterable[str]) -> tuple[dict, ...]:
    """None of ``names`` ends in or on ``receptacle`` (the relation a check of putting it there would use);
    things that start there are left out."""
    there = set(scene.holding(receptacle))
    return tuple(
        {in_or_on(scene.type(n), scene.type(receptacle)): [n, receptacle], "not": True}
        for n in names
        if n not in there and n != receptacle
    )


def stays_shut(scene: Scene, used: Iterable[str] = ()) -> tuple[dict, ...]:
    """Every drawer and door of the world but ``used`` that starts closed ends closed (within :data:`DRAWER_SHUT`
    or :data:`DOOR_SHUT`)."""
    skip = set(used)
    parts = [p for p in scene.world.part_names() if kind_of(p) in ("drawer", "door") and p not in skip]
    return tuple(
        {"joint": p, "above": DRAWER_SHUT if kind_of(p) == "drawer" else DOOR_SHUT, "not": True}
        for p in parts
        if not scene.opened(p)
    )


def others(scene: Scene, *names: str) -> list[str]:
    """The pickable things of the world other than ``names``."""
    return [n for n, o in scene.placements.items() if o.type.pickable and n not in names]


__all__ = ["DOOR_SHUT", "DRAWER_SHUT", "STAY_WITHIN", "others", "stays_out", "stays_put", "stays_shut"]
