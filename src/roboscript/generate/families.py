"""Template task families: a task written once for any world where it makes sense, with its checks and its oracle
program following from the template.

Each family looks at a world (:class:`~roboscript.generate.scene.Scene`), picks what its task is about among the
things that fit (an object small enough for the bowl, two blocks that stack, a drawer of a cabinet) and returns a
:class:`TemplateTask`, or None where the world offers nothing for it. Choices are drawn from ``rng``, so a world and
a seed give the same task.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from roboscript.generate.describe import ORDINALS
from roboscript.generate.programs import (
    CLOSE_DRAWER,
    OPEN_DOOR,
    OPEN_DRAWER,
    PICK_FROM_SIDE,
    PUT,
    SPOT_BESIDE,
    Program,
    move_into,
    move_to,
    words,
)
from roboscript.generate.scene import DRAWER_HEIGHT_LIMIT, KINDS, Scene, fits, in_or_on, room_for
from roboscript.generate.stays import DRAWER_SHUT, others, stays_out, stays_put, stays_shut
from roboscript.objects.reading import said_colour, said_kind
from roboscript.sim.world_file import ROBOT_BASE_XY

NEAR_GAP = 0.03  # how far beside its target the oracle puts a thing (the `near` check allows 8 cm)


@dataclass(frozen=True)
class TemplateTask:
    """One instance of a family: the instruction, the checks (in the task file's form: what must be done, then
    what must stay as it was, :mod:`roboscript.generate.stays`) and the oracle program."""

    family: str
    instruction: str
    checks: tuple[dict, ...]
    program: str


Family = Callable[[Scene, np.random.Generator], "TemplateTask | None"]


def _one(rng: np.random.Generator, items: list):
    return items[int(rng.integers(len(items)))]


def _say(rng: np.random.Generator, phrasings: tuple[str, ...], **names: str) -> str:
    return _one(rng, list(phrasings)).format(**{k: words(v) for k, v in names.items()})


def _put_into(scene: Scene, thing: str, receptacle: str) -> dict:
    return {in_or_on(scene.type(thing), scene.type(receptacle)): [thing, receptacle]}


def into_container(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Put a thing into a bowl or a basket."""
    pairs = [
        (t, c)
        for c in scene.containers
        for t in scene.on_table
        if room_for([scene.type(t)], scene.type(c), [scene.type(h) for h in scene.holding(c)])
    ]
    if not pairs:
        return None
    thing, container = _one(rng, pairs)
    phrasings = ("put the {t} into the {c}", "place the {t} in the {c}", "move the {t} into the {c}")
    instruction = _say(rng, phrasings, t=thing, c=container)
    program = move_into(Program(instruction), thing, container)
    checks = (_put_into(scene, thing, container), *stays_out(scene, container, others(scene, thing)))
    return TemplateTask("into_container", instruction, checks, program.text())


def onto_plate(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Put a thing onto a plate or a saucer."""
    pairs = [
        (t, p)
        for p in scene.plates
        if not scene.holding(p)
        for t in scene.on_table
        if fits(scene.type(t), scene.type(p))
    ]
    if not pairs:
        return None
    thing, plate = _one(rng, pairs)
    phrasings = ("put the {t} on the {p}", "place the {t} onto the {p}", "set the {t} down on the {p}")
    instruction = _say(rng, phrasings, t=thing, p=plate)
    program = move_into(Program(instruction), thing, plate, onto=True)
    checks = ({"on": [thing, plate]}, *stays_out(scene, plate, others(scene, thing)))
    return TemplateTask("onto_plate", instruction, checks, program.text())


def into_drawer(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Open a drawer of the cabinet and put a thing into it."""
    things = [t for t in scene.on_table if scene.type(t).size[2] <= DRAWER_HEIGHT_LIMIT]
    # A drawer pulled out stands in the way of the hand coming for the handles below it.
    closed = [d for d in scene.drawers if not scene.opened(d)] if not scene.any_open else []
    if not closed or not things:
        return None
    drawer, thing = _one(rng, closed), _one(rng, things)
    handle = scene.handle_of(drawer)
    ordinal = ORDINALS[scene.drawers.index(drawer)]
    instruction = _one(
        rng,
        [
            f"open the {ordinal} drawer of the cabinet and put the {words(thing)} into it",
            f"put the {words(thing)} into the {ordinal} drawer; the drawer is closed, open it first",
        ],
    )
    program = Program(instruction).use(OPEN_DRAWER)
    program.step(
        f"The drawer is closed: pull it open by its handle ({handle}).", f"open_drawer({drawer!r}, {handle!r})"
    )
    move_into(program, thing, drawer)
    checks = ({"joint": drawer, "above": 0.1}, {"in": [thing, drawer]}, *stays_shut(scene, [drawer]))
    return TemplateTask("into_drawer", instruction, checks, program.text())


def stack(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Stack a block or a small box on top of a larger box or block."""
    flat_topped = [t for t in scene.on_table if scene.type(t).shape == "box" and scene.type(t).size[2] <= 0.07]
    pairs = []
    for top in flat_topped:
        diagonal = math.hypot(*scene.type(top).size[:2])
        for base in flat_topped:
            # In any turn, the top's box stays over the base's: the `on` check compares boxes aligned with the world.
            if base != top and diagonal <= float(min(scene.type(base).size[:2])) + 0.003:
                pairs.append((top, base))
    if not pairs:
        return None
    top, base = _one(rng, pairs)
    phrasings = ("stack the {t} on top of the {b}", "put the {t} on the {b}", "place the {t} on top of the {b}")
    instruction = _say(rng, phrasings, t=top, b=base)
    program = Program(instruction)
    program.step(
        f"The {words(base)}'s top is where the {words(top)} goes.", f"base = get_object_center_position({base!r})"
    )
    move_to(program, top, "base", f"Pick up the {words(top)} and set it down on the {words(base)}.")
    return TemplateTask("stack", instruction, ({"on": [top, base]}, *stays_put([base])), program.text())


def swap(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Swap the places of two things on the table."""
    things = scene.on_table
    pairs = [
        (a, b) for i, a in enumerate(things) for b in things[i + 1 :] if abs(scene.radius(a) - scene.radius(b)) <= 0.03
    ]
    if not pairs:
        return None
    a, b = _one(rng, pairs)
    phrasings = ("swap the positions of the {a} and the {b}", "exchange the places of the {a} and the {b}")
    instruction = _say(rng, phrasings, a=a, b=b)
    program = Program(instruction)
    program.step(
        f"Remember where the {words(a)} and the {words(b)} are now.",
        f"{a}_position = get_object_center_position({a!r})",
        f"{b}_position = get_object_center_position({b!r})",
    )
    move_into(program, a, "table").plan[-1] = f"Put the {words(a)} aside on the table, out of the way."
    move_to(program, b, f"{a}_position", f"Put the {words(b)} where the {words(a)} was.")
    move_to(program, a, f"{b}_position", f"Put the {words(a)} where the {words(b)} was.")
    rest = [n for n in scene.placements if n not in (a, b)]
    checks = ({"at": a, "start_of": b}, {"at": b, "start_of": a}, *stays_put(rest))
    return TemplateTask("swap", instruction, checks, program.text())


# The kinds by library category that sorting enumerated its options with when the packaged generated suite was
# made: enumerating them so still gives that suite's tasks from its worlds and seed (the checks follow the words).
_LIBRARY_KINDS: dict[str, frozenset[str]] = {
    "fruit": frozenset({"apple", "orange", "lemon", "lime", "plum", "peach", "strawberry", "banana", "pear"}),
    "ball": frozenset({"tennis ball", "baseball", "golf ball"}),
    "block": frozenset({"block", "cube"}),
    "box": frozenset({"box"}),
    "toy": frozenset({"toy bus", "toy car"}),
    "drinkware": frozenset({"cup", "mug"}),
    "bottle": frozenset({"bottle", "can"}),
}


def _library_groups(scene: Scene, by: str) -> dict[str, list[str]]:
    """Things on the table by the colour they are drawn in or their library category's kind: how sorting tasks
    are drawn (see :data:`_LIBRARY_KINDS`), not what they check."""
    groups: dict[str, list[str]] = {}
    for thing in scene.on_table:
        kind = scene.type(thing)
        key = (
            kind.appearance
            if by == "colour"
            else next((k for k, c in _LIBRARY_KINDS.items() if kind.category in c), None)
        )
        if key is not None:
            groups.setdefault(key, []).append(thing)
    return groups


def _read_group(scene: Scene, by: str, key: str, receptacle: str) -> list[str]:
    """What "the <key> objects" (or "the <kind>") are to a reader of the instruction: every pickable thing whose
    name says that colour or kind (:mod:`roboscript.objects.reading`), on the table or on another receptacle, and
    not already in or on ``receptacle``."""
    say = said_colour if by == "colour" else said_kind
    there = set(scene.holding(receptacle))
    return [n for n, o in scene.placements.items() if o.type.pickable and n not in there and say(n) == key]


def sort(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Sort things by colour (each onto the receptacle of its colour) or by kind (one kind into each receptacle)."""
    options = []
    colours = _library_groups(scene, "colour")
    for receptacle in scene.receptacles:
        group = colours.get(scene.type(receptacle).appearance, [])
        if group and not scene.holding(receptacle) and room_for([scene.type(t) for t in group], scene.type(receptacle)):
            options.append(("colour", scene.type(receptacle).appearance, group, receptacle))
    kinds = _library_groups(scene, "kind")
    for kind, group in kinds.items():
        for receptacle in scene.receptacles:
            empty = not scene.holding(receptacle)
            if len(group) >= 2 and empty and room_for([scene.type(t) for t in group], scene.type(receptacle)):
                options.append(("kind", kind, group, receptacle))
    if not options:
        return None
    by, key, group, receptacle = _one(rng, options)
    # A second group sorted into another receptacle, where the world has one.
    seconds = [o for o in options if o[0] == by and o[1] != key and o[3] != receptacle]
    chosen = [(key, receptacle)] + ([_one(rng, seconds)[1::2]] if seconds else [])
    read = [(key, _read_group(scene, by, key, receptacle), receptacle) for key, receptacle in chosen]
    if not all(group for _, group, _ in read) or not all(
        room_for([scene.type(t) for t in group], scene.type(r)) for _, group, r in read
    ):
        return None  # the words select nothing, or more than fits: no fair task here
    said = []
    for key, _, receptacle in read:
        what = f"the {words(key)} objects" if by == "colour" else f"the {KINDS[key]}"
        said.append(f"{what} {'on' if scene.type(receptacle).shape == 'flat' else 'into'} the {words(receptacle)}")
    instruction = f"sort the objects on the table by {by}: put " + " and ".join(said)
    program = Program(instruction)
    checks = []
    for _, group, receptacle in read:
        for thing in group:
            move_into(program, thing, receptacle, onto=scene.type(receptacle).shape == "flat")
            checks.append(_put_into(scene, thing, receptacle))
    say = said_colour if by == "colour" else said_kind
    for key, _, receptacle in read:
        # Things whose names say another colour or kind stay off; those whose names say none are left open.
        checks += stays_out(scene, receptacle, [n for n in others(scene) if say(n) not in (None, key)])
    return TemplateTask(f"sort_by_{by}", instruction, tuple(checks), program.text())


def clear_table(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Clear the table: every thing lying on it into one container."""
    things = scene.on_table
    options = [
        c
        for c in scene.containers
        if len(things) >= 2
        and room_for([scene.type(t) for t in things], scene.type(c), [scene.type(h) for h in scene.holding(c)])
    ]
    if not options:
        return None
    container = _one(rng, options)
    left = sorted({scene.type(r).category for r in scene.receptacles})
    plural = {"basket": "baskets", "bowl": "bowls", "footed bowl": "bowls", "plate": "plates", "saucer": "saucers"}
    leaving = " and ".join(dict.fromkeys(plural.get(c, c) for c in left))
    instruction = (
        f"clear the table by putting every object lying on it into the {words(container)}; "
        f"leave the {leaving} where they are"
    )
    program = Program(instruction)
    for thing in things:
        move_into(program, thing, container)
    checks = (*(_put_into(scene, t, container) for t in things), *stays_put(scene.receptacles))
    return TemplateTask("clear_table", instruction, checks, program.text())


def _free_beside(scene: Scene, thing: str, target: str) -> bool:
    """Whether some side of ``target`` has room for ``thing`` (as the oracle's spot_beside looks for it)."""
    radius = scene.radius(thing)
    others = [(scene.position(o), scene.radius(o)) for o in scene.placements if o not in (thing, target)]
    others += [(np.array(c.position), math.hypot(c.depth / 2 + 0.05, c.width / 2)) for c in scene.world.cabinets]
    center = scene.position(target)
    for side in ([0, 1], [0, -1], [-1, 0], [1, 0]):
        spot = center + np.array(side) * (scene.radius(target) + radius + NEAR_GAP)
        if not 0.32 < np.linalg.norm(spot - np.array([-0.45, 0.0])) < 0.68:
            continue
        if all(np.linalg.norm(spot - p) > radius + r + 0.01 for p, r in others):
            return True
    return False


def next_to(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Put a thing next to another one."""
    targets = [o.name for o in scene.world.objects if o.support_kind == "table"]
    pairs = [(t, g) for t in scene.on_table for g in targets if g != t and _free_beside(scene, t, g)]
    if not pairs:
        return None
    thing, target = _one(rng, pairs)
    phrasings = ("put the {t} next to the {g}", "place the {t} beside the {g}", "move the {t} next to the {g}")
    instruction = _say(rng, phrasings, t=thing, g=target)
    obstacles = [n for n in scene.world.object_names() if n not in (thing, target)]
    obstacles += [c.name for c in scene.world.cabinets]
    program = Program(instruction).use(SPOT_BESIDE)
    program.step(
        f"Find a free place on the table beside the {words(target)}.",
        f"spot = spot_beside({target!r}, {thing!r}, {obstacles!r})",
    )
    move_to(program, thing, "spot", f"Pick up the {words(thing)} and put it down there.")
    return TemplateTask("next_to", instruction, ({"near": [thing, target]}, *stays_put([target])), program.text())


DOOR_OPEN = 0.7  # radians (40 degrees) past which a door counts as open


def open_door(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Open a door of the cabinet (a revolute joint: an arc about its hinge)."""
    doors = [d for d in scene.doors if not scene.opened(d)] if not scene.any_open else []
    if not doors:
        return None
    door = _one(rng, doors)
    which = "the cabinet door" if len(scene.doors) == 1 else f"the {ORDINALS[scene.doors.index(door)]} cabinet door"
    instruction = _one(rng, [f"open {which}", f"swing {which} open", f"open {which} wide"])
    handle = scene.handle_of(door)
    program = Program(instruction).use(OPEN_DOOR)
    program.step(
        f"The door turns on its hinge: swing it open by its handle ({handle}).", f"open_door({door!r}, {handle!r})"
    )
    checks = ({"joint": door, "above": DOOR_OPEN}, *stays_shut(scene, [door]))
    return TemplateTask("open_door", instruction, checks, program.text())


def close_drawer(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Close a drawer the world starts with pulled out."""
    opened = [d for d in scene.drawers if scene.opened(d)]
    if not opened:
        return None
    drawer = _one(rng, opened)
    ordinal = ORDINALS[scene.drawers.index(drawer)]
    instruction = _one(
        rng, ["close the open drawer", f"close the {ordinal} drawer of the cabinet", "push the open drawer shut"]
    )
    handle = scene.handle_of(drawer)
    program = Program(instruction).use(CLOSE_DRAWER)
    program.step(
        f"The {ordinal} drawer is pulled out: push it shut by its handle ({handle}).",
        f"close_drawer({drawer!r}, {handle!r})",
    )
    checks = ({"joint": drawer, "above": DRAWER_SHUT, "not": True}, *stays_shut(scene, [drawer]))
    return TemplateTask("close_drawer", instruction, checks, program.text())


# What a hand carries into a compartment from the side: its narrower side within the fingers' opening with room to
# spare, tall enough to be gripped level above the floor, and low enough to pass under the panel above with the hand.
SIDE_GRIP_WIDTH = 0.066
SIDE_GRIP_HEIGHT = (0.04, 0.11)
SIDE_GRIP_REACH = 0.6  # metres from the robot's base: a level hand low over the table reaches less far than one above


def into_cupboard(scene: Scene, rng: np.random.Generator) -> TemplateTask | None:
    """Open a cabinet door and put a thing into the compartment behind it (carried in from the side)."""
    doors = [d for d in scene.compartments if not scene.opened(d)] if not scene.any_open else []
    things = [
        t
        for t in scene.on_table
        if float(min(scene.type(t).size[:2])) <= SIDE_GRIP_WIDTH
        and SIDE_GRIP_HEIGHT[0] <= float(scene.type(t).size[2]) <= SIDE_GRIP_HEIGHT[1]
        and float(np.linalg.norm(scene.position(t) - ROBOT_BASE_XY)) <= SIDE_GRIP_REACH
    ]
    if not doors or not things:
        return None
    door, thing = _one(rng, doors), _one(rng, things)
    which = "the cabinet door" if len(scene.doors) == 1 else f"the {ORDINALS[scene.doors.index(door)]} cabinet door"
    instruction = _one(
        rng,
        [
            f"open {which} and put the {words(thing)} in the cupboard behind it",
            f"put the {words(thing)} into the cabinet behind its door; the door is closed, open it first",
            f"open {which}, then place the {words(thing)} inside the cabinet",
        ],
    )
    handle = scene.handle_of(door)
    program = Program(instruction).use(OPEN_DOOR, PICK_FROM_SIDE, PUT)
    program.step(
        f"The door turns on its hinge: swing it open by its handle ({handle}).", f"open_door({door!r}, {handle!r})"
    )
    program.step(
        f"Things go in through the door under the shelf above, so grip the {words(thing)} from the side and put it "
        "in; the hand backs out the way it came.",
        f"pick_from_side({thing!r})",
        f"put({thing!r}, parse_place_pose(object_name={thing!r}, receptacle_name={door!r}))",
    )
    checks = ({"joint": door, "above": DOOR_OPEN}, {"in": [thing, door]}, *stays_shut(scene, [door]))
    return TemplateTask("into_cupboard", instruction, checks, program.text())


# The families of the generated suite's version 1, in their order (see roboscript.generate.suite.world_tasks).
FIRST_FAMILIES = (
    "into_container", "onto_plate", "into_drawer", "stack", "swap", "sort", "clear_table", "next_to"
)  # fmt: skip
FAMILIES: dict[str, Family] = {
    "into_container": into_container,
    "onto_plate": onto_plate,
    "into_drawer": into_drawer,
    "stack": stack,
    "swap": swap,
    "sort": sort,
    "clear_table": clear_table,
    "next_to": next_to,
    "open_door": open_door,
    "close_drawer": close_drawer,
    "into_cupboard": into_cupboard,
}
