"""A scene in words, from a world's state: where each thing is (in which bowl, on which plate, in which drawer, or
where on the table), what each receptacle holds, and which drawers are open.

The relations are the benchmark's own checks (``in``, ``on``) evaluated on the world's ground truth, so a scene
description and a task's checks never disagree about where something is. Each thing is named in words with its
colour and, in brackets, by the name programs use: "The red apple (apple) is in the white bowl (white_bowl)."
"""

from __future__ import annotations

from pathlib import Path

from roboscript.bench.checks import Check
from roboscript.names import kind_of
from roboscript.sim.ground_truth import GroundTruth
from roboscript.sim.world_file import WorldSpec

OPEN_ABOVE = 0.03  # a drawer pulled out further than this is open
ORDINALS = ("top", "second", "third", "fourth", "fifth", "sixth")
NUMBERS = ("no", "one", "two", "three", "four", "five", "six")


def thing_words(world: WorldSpec, name: str) -> str:
    """``the red apple (apple)``: the name in words, with the colour where the name does not say it."""
    placement = next(o for o in world.objects if o.name == name)
    said = name.replace("_", " ")
    colour = placement.type.color.replace("_", " ")
    if colour not in said:
        said = f"{colour} {said}"
    return f"the {said} ({name})"


def table_region(x: float, y: float) -> str:
    """Where on the table, as the robot (at x = -0.45, facing +x) sees it."""
    depth = "near the robot" if x < -0.15 else "far from the robot" if x > 0.05 else "in the middle of the table"
    side = "on the left" if y > 0.15 else "on the right" if y < -0.15 else ""
    return f"{depth}, {side}" if side else depth


def _holds(gt: GroundTruth, thing: str, receptacle: str, kind: str) -> bool:
    return Check(kind, thing, receptacle).evaluate(gt).passed


def _where(world: WorldSpec, gt: GroundTruth, name: str) -> tuple[str, str | None]:
    """Where ``name`` is, in words, and the receptacle it is in or on (None on the table)."""
    drawers = [p for p in world.part_names() if kind_of(p) == "drawer"]
    for drawer in drawers:
        if _holds(gt, name, drawer, "in"):
            cabinet, _, _ = drawer.partition(".")
            return f"in the {_drawer_words(world, drawer)} of the {cabinet} ({drawer})", drawer
    for other in world.objects:
        if other.name == name or other.type.pickable:
            continue
        if other.type.shape != "flat" and _holds(gt, name, other.name, "in"):
            return f"in {thing_words(world, other.name)}", other.name
        if _holds(gt, name, other.name, "on"):
            word = "on" if other.type.shape == "flat" else "in"
            return f"{word} {thing_words(world, other.name)}", other.name
    for other in world.objects:
        if other.name != name and other.type.pickable and _holds(gt, name, other.name, "on"):
            box, below = gt.box(name), gt.box(other.name)
            if box.lower[2] >= below.upper[2] - 0.02:
                return f"on top of {thing_words(world, other.name)}", other.name
    center = gt.box(name).center
    return f"on the table, {table_region(float(center[0]), float(center[1]))}", None


def _drawer_words(world: WorldSpec, drawer: str) -> str:
    cabinet, _, _ = drawer.partition(".")
    drawers = [p for p in world.part_names() if kind_of(p) == "drawer" and p.startswith(f"{cabinet}.")]
    return f"{ORDINALS[drawers.index(drawer)]} drawer"


def describe_scene(world: WorldSpec, gt: GroundTruth) -> str:
    """The scene in sentences: furniture and its drawers, then each object, then what each receptacle holds."""
    sentences = []
    for cabinet in world.cabinets:
        drawers = [p for p in cabinet.part_names() if kind_of(p) == "drawer"]
        doors = [p for p in cabinet.part_names() if kind_of(p) == "door"]
        parts = [f"{NUMBERS[len(drawers)]} drawers" if drawers else "", f"{NUMBERS[len(doors)]} doors" if doors else ""]
        region = table_region(*cabinet.position)
        sentences.append(f"A cabinet ({cabinet.name}) with {' and '.join(p for p in parts if p)} stands {region}.")
        for drawer in drawers:
            opening = gt.joint(drawer).value
            state = f"open ({opening * 100:.0f} cm)" if opening > OPEN_ABOVE else "closed"
            sentences.append(f"Its {_drawer_words(world, drawer)} ({drawer}) is {state}.")
    held: dict[str, list[str]] = {}
    for o in world.objects:
        where, receptacle = _where(world, gt, o.name)
        sentences.append(f"{_capital(thing_words(world, o.name))} is {where}.")
        if receptacle is not None:
            held.setdefault(receptacle, []).append(o.name)
    for o in world.objects:
        if o.type.container and not o.type.pickable and o.name not in held:
            sentences.append(f"{_capital(thing_words(world, o.name))} is empty.")
    return " ".join(sentences)


def describe_world(world: str | Path | WorldSpec, seed: int = 0, randomize: bool = False) -> str:
    """Builds ``world`` in simulation, lets it settle, and describes it."""
    from roboscript.backends.mujoco_backend import MujocoBackend

    with MujocoBackend(world, seed=seed, randomize=randomize) as backend:
        return describe_scene(backend.sim_world.spec, backend.ground_truth)


def _capital(text: str) -> str:
    return text[:1].upper() + text[1:]
