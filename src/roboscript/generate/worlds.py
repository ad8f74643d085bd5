"""Random tabletop worlds from a recipe: valid world files, the same ones for the same seed.

Things are placed one at a time, the large receptacles first: a place is drawn within the recipe's region and the
arm's reach ring, away from the cabinet's drawers, and kept only if the world file it makes passes the world
file's own validation (nothing overlaps, nothing leaves the table or blocks the robot). A world is therefore valid
by the same rules as a hand-written one.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import yaml

from roboscript.errors import InvalidArgumentError
from roboscript.generate.recipe import Recipe, row_kind
from roboscript.generate.scene import DRAWERS_USED
from roboscript.objects import get_object_type
from roboscript.sim.world_file import ROBOT_BASE_XY, WorldFileError, WorldSpec, parse_world, placements_overlap

PLACE_TRIES = 200
CABINET_DEPTH = 0.46  # a cabinet's footprint along x, handles included (world files' default depth, 0.36, and 0.1)
WORLD_TRIES = 20


class GenerationError(WorldFileError):
    """No valid arrangement was found for a recipe and seed."""


@dataclass(frozen=True)
class GeneratedWorld:
    """A generated world: its file's data, validated, and the seed it came from."""

    name: str
    data: dict
    spec: WorldSpec
    seed: tuple[int, int]

    def yaml(self) -> str:
        return yaml.safe_dump(self.data, sort_keys=False, width=120)


def world_seed(seed: int, index: int) -> np.random.Generator:
    """The random stream of world ``index`` of a run with ``seed``: independent of how many worlds are made."""
    return np.random.default_rng(np.random.SeedSequence([seed, index]))


def generate_world(recipe: Recipe, seed: int, index: int, name: str | None = None) -> GeneratedWorld:
    """World ``index`` of a run with ``seed``; raises :class:`GenerationError` if no arrangement fits."""
    rng = world_seed(seed, index)
    name = name or f"gen_{seed}_{index:03d}"
    for _ in range(WORLD_TRIES):
        data = _arrange(recipe, rng, name, f"recipe {recipe.name}, seed {seed}, world {index}")
        if data is not None:
            return GeneratedWorld(name, data, parse_world(data, f"<generated {name}>"), (seed, index))
    raise GenerationError(
        f"<generated {name}>",
        "objects",
        f"recipe {recipe.name!r} fit no arrangement in {WORLD_TRIES} tries (seed {seed}, world {index}); "
        "widen its region or draw fewer things",
    )


def _arrange(recipe: Recipe, rng: np.random.Generator, name: str, origin: str) -> dict | None:
    """One attempt at a world's data; None when the objects drawn did not all find a place."""
    data: dict = {"name": name, "description": f"Generated ({origin}).", "robot": recipe.robot}
    cabinet = recipe.cabinet
    if cabinet is not None and rng.random() < cabinet.probability:
        rows: list = list(cabinet.rows)
        if cabinet.start_open and rng.random() < cabinet.start_open:
            drawers = [k for k, row in enumerate(rows) if row_kind(row) == "drawer"][:DRAWERS_USED]
            k = drawers[int(rng.integers(len(drawers)))]
            pulled = cabinet.open_distance.low + rng.random() * (cabinet.open_distance.high - cabinet.open_distance.low)
            entry = rows[k] if isinstance(rows[k], dict) else {"kind": "drawer"}
            rows[k] = {**entry, "open": round(float(pulled), 3)}
        furniture = {"name": "cabinet", "type": "cabinet", "position": list(cabinet.position)}
        if cabinet.yaw:
            furniture["yaw"] = cabinet.yaw
        data["furniture"] = [{**furniture, "width": cabinet.width, "rows": rows}]
    data["objects"] = []
    receptacles = _draw_receptacles(recipe, rng)
    for type_name in receptacles:
        if not _place_on_table(recipe, rng, data, type_name):
            return None
    targets = [r for r in receptacles if get_object_type(r).interior is not None]
    holding: set[str] = set()
    for type_name in _draw_objects(recipe, rng, receptacles):
        if targets and rng.random() < recipe.start_in_receptacle:
            free = [r for r in targets if r not in holding and _fits_in(type_name, r)]
            if free:
                support = free[int(rng.integers(len(free)))]
                entry = {"name": type_name, "type": type_name, "on": support, "position": [0.0, 0.0],
                         "yaw": _yaw(recipe, rng)}  # fmt: skip
                if _valid(data, entry):
                    data["objects"].append(entry)
                    holding.add(support)
                    continue
        if not _place_on_table(recipe, rng, data, type_name):
            return None
    if recipe.randomize:
        data["randomize"] = dict(recipe.randomize)
    return data


def _draw_receptacles(recipe: Recipe, rng: np.random.Generator) -> list[str]:
    low, high = recipe.receptacle_count
    count = int(rng.integers(low, high + 1))
    pool = list(recipe.receptacle_types)
    chosen: list[str] = []
    while pool and len(chosen) < count:
        pick = pool.pop(int(rng.integers(len(pool))))
        chosen.append(pick)
        if pick in recipe.at_most_one:
            pool = [p for p in pool if p not in recipe.at_most_one]
    # The large ones first: they are the hardest to fit.
    return sorted(chosen, key=lambda n: -float(np.prod(get_object_type(n).size[:2])))


def _draw_objects(recipe: Recipe, rng: np.random.Generator, receptacles: list[str]) -> list[str]:
    low, high = recipe.object_count
    count = int(rng.integers(low, high + 1))
    # Matched by the colour things are drawn in, as the packaged generated suite's worlds were.
    colours = {get_object_type(r).appearance for r in receptacles}
    pool = list(recipe.object_types)
    chosen: list[str] = []
    while pool and len(chosen) < count:
        matching = [p for p in pool if get_object_type(p).appearance in colours]
        source = matching if matching and rng.random() < recipe.match_colour else pool
        pick = source[int(rng.integers(len(source)))]
        pool.remove(pick)
        chosen.append(pick)
    return chosen


def _yaw(recipe: Recipe, rng: np.random.Generator) -> float:
    return round(float(rng.uniform(-recipe.yaw_deg, recipe.yaw_deg)), 1)


def _place_on_table(recipe: Recipe, rng: np.random.Generator, data: dict, type_name: str) -> bool:
    radius = get_object_type(type_name).footprint_radius
    for _ in range(PLACE_TRIES):
        x = float(rng.uniform(recipe.region_x.low, recipe.region_x.high))
        y = float(rng.uniform(recipe.region_y.low, recipe.region_y.high))
        if not _allowed(recipe, data, x, y, radius):
            continue
        entry = {"name": type_name, "type": type_name, "position": [round(x, 3), round(y, 3)],
                 "yaw": _yaw(recipe, rng)}  # fmt: skip
        if _valid(data, entry, recipe.spacing):
            data["objects"].append(entry)
            return True
    return False


def _allowed(recipe: Recipe, data: dict, x: float, y: float, radius: float) -> bool:
    """Within the reach ring, and (with a cabinet) clear of where its drawers slide out."""
    if math.dist((x, y), ROBOT_BASE_XY) not in recipe.reach:
        return False
    cabinet = recipe.cabinet
    if cabinet is None or "furniture" not in data:
        return True
    clear_x, clear_y = cabinet.keep_clear_x, cabinet.keep_clear_y
    if clear_x.low - radius < x < clear_x.high + radius and clear_y.low - radius < y < clear_y.high + radius:
        return False
    # Room beside the cabinet's sides for a hand (and its wrist) coming for a thing there.
    half = np.array([CABINET_DEPTH / 2, cabinet.width / 2])
    if abs(math.sin(math.radians(cabinet.yaw))) > 0.7:  # turned a quarter: its depth runs along y
        half = half[::-1]
    half = half + cabinet.spacing + radius
    return bool(np.any(np.abs(np.subtract((x, y), cabinet.position)) > half))


def _valid(data: dict, entry: dict, spacing: float = 0.0) -> bool:
    """Whether the world with ``entry`` added is valid, and ``entry`` (on the table) keeps ``spacing`` from the
    other things on the table: room for the fingers of a hand that comes for either."""
    candidate = {**data, "objects": [*data["objects"], entry]}
    try:
        world = parse_world(candidate, "<candidate>")
    except WorldFileError:
        return False
    added = world.objects[-1]
    if added.support_kind != "table":
        return True
    return not any(placements_overlap(added, o, spacing) for o in world.objects[:-1] if o.support_kind == "table")


def _fits_in(type_name: str, receptacle: str) -> bool:
    """Whether ``type_name`` stands inside ``receptacle``'s interior with a centimetre to spare on each side."""
    lower, upper = get_object_type(receptacle).interior
    inner = np.subtract(upper, lower)[:2]
    size = np.sort(get_object_type(type_name).size[:2])
    return bool(np.all(size + 0.02 <= np.sort(inner)))


def generate_worlds(
    recipe: Recipe,
    count: int,
    seed: int,
    out: str | Path,
    prefix: str | None = None,
    on_world: Callable[[GeneratedWorld, Path], None] | None = None,
) -> list[Path]:
    """Writes ``count`` worlds (``<prefix>_<i>.yaml``) into ``out`` and returns their paths; ``on_world`` is told
    of each as it is written (a top view, progress)."""
    if count < 1:
        raise InvalidArgumentError(f"count must be at least 1, got {count}")
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    for index in range(count):
        name = f"{prefix or f'gen_{seed}'}_{index:03d}"
        world = generate_world(recipe, seed, index, name)
        path = out / f"{name}.yaml"
        path.write_text(world.yaml())
        paths.append(path)
        if on_world is not None:
            on_world(world, path)
    return paths
