"""World recipes: what a random tabletop is made of, as a validated data file (``roboscript/generate/*.yaml``).

A recipe names the robot, an optional cabinet with the room its drawers need, the receptacles and pickable types
to draw from the object library with how many of each, and the region of the table where things may stand. Every
problem is a :class:`RecipeFileError` naming the file, the entry and what is wrong.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from roboscript.datafile import DataFileError, PackagedFiles, Reader, read_data_file
from roboscript.errors import unknown_name
from roboscript.objects import object_types
from roboscript.objects.library import OBJECT_LISTING
from roboscript.sim.world_file import VALID_ROBOTS

DEFAULT_RECIPE = "tabletop"
_FIELDS = {
    "recipe", "description", "robot", "cabinet", "region", "spacing", "receptacles", "objects", "yaw", "randomize"
}  # fmt: skip


class RecipeFileError(DataFileError):
    """A world recipe that cannot be loaded; the message names the file, the entry and the problem."""

    kind = "recipe"


@dataclass(frozen=True)
class Range:
    """A closed interval ``[low, high]``."""

    low: float
    high: float

    def __contains__(self, value: float) -> bool:
        return self.low <= value <= self.high


@dataclass(frozen=True)
class CabinetRecipe:
    probability: float
    position: tuple[float, float]
    width: float
    rows: tuple[str | dict, ...]  # a row's kind, or a world file's row entry (kind, height, hinge)
    keep_clear_x: Range
    keep_clear_y: Range
    spacing: float  # kept between the cabinet's sides and anything on the table
    # The chance that one of its top two drawers starts pulled out, and how far (metres): worlds for closing one.
    start_open: float = 0.0
    open_distance: Range = Range(0.0, 0.0)
    yaw: float = 0.0  # degrees; 0: the front faces +x, 180: it faces the robot across the table


@dataclass(frozen=True)
class Recipe:
    """A validated recipe. ``receptacle_types`` and ``object_types`` are library type names."""

    name: str
    source: str
    description: str
    robot: str
    cabinet: CabinetRecipe | None
    region_x: Range
    region_y: Range
    reach: Range
    spacing: float
    receptacle_count: tuple[int, int]
    receptacle_types: tuple[str, ...]
    at_most_one: frozenset[str]
    object_count: tuple[int, int]
    object_types: tuple[str, ...]
    match_colour: float
    start_in_receptacle: float
    yaw_deg: float
    randomize: dict


def _range(entry: Reader, key: str) -> Range:
    low, high = entry.vector(key, (2,))
    if low > high:
        entry.fail(f"field {key!r} must be [low, high] with low <= high, got {[low, high]}")
    return Range(low, high)


def _count(entry: Reader) -> tuple[int, int]:
    low, high = entry.vector("count", (2,))
    if low != int(low) or high != int(high) or not 0 <= low <= high:
        entry.fail(f"field 'count' must be [min, max], whole numbers with 0 <= min <= max, got {[low, high]}")
    return int(low), int(high)


def _probability(entry: Reader, key: str, default: float) -> float:
    value = entry.number(key, default)
    if not 0.0 <= value <= 1.0:
        entry.fail(f"field {key!r} is a probability, within 0..1; got {value}")
    return value


def _spacing(entry: Reader) -> float:
    value = entry.number("spacing", 0.0)
    if not 0.0 <= value <= 0.2:
        entry.fail(f"field 'spacing' is the gap kept between things on the table, within 0..0.2 m; got {value}")
    return value


def _types(entry: Reader, names: Any, what: str) -> tuple[str, ...]:
    library = object_types()
    if not isinstance(names, list) or not names:
        entry.fail(f"{what} must be a non-empty list of object types (see `roboscript objects`), got {names!r}")
    for name in names:
        if name not in library:
            entry.fail(f"{what}: " + unknown_name("object type", name, library, OBJECT_LISTING))
    return tuple(names)


def row_kind(row: object) -> str | None:
    """A recipe row's kind: the row itself (``drawer``) or its entry's ``kind``."""
    if isinstance(row, dict):
        return row.get("kind")
    return row if isinstance(row, str) else None


def _parse_cabinet(source: str, data: Any) -> CabinetRecipe | None:
    if data is None:
        return None
    fields = {"probability", "position", "yaw", "width", "rows", "keep_clear", "spacing", "start_open"}
    entry = Reader(source, "cabinet", data, fields, RecipeFileError)
    opening = Reader(
        source, "cabinet.start_open", entry.data.get("start_open", {}), {"probability", "distance"}, RecipeFileError
    )
    distance = _range(opening, "distance") if "distance" in opening.data else Range(0.0, 0.0)
    if distance.low < 0.0 or distance.high > 0.25:
        opening.fail(f"field 'distance' is how far a drawer starts pulled out, within 0..0.25 m; got {distance}")
    rows = entry.data.get("rows", ["drawer", "drawer", "drawer"])
    if not isinstance(rows, list) or not rows or any(row_kind(r) not in ("drawer", "door") for r in rows):
        entry.fail(
            f"field 'rows' must be a non-empty list of 'drawer', 'door' or row entries ({{kind: door, height: 0.2}}), "
            f"got {rows!r}"
        )
    clear = Reader(source, "cabinet.keep_clear", entry.required("keep_clear"), {"x", "y"}, RecipeFileError)
    return CabinetRecipe(
        probability=_probability(entry, "probability", 0.5),
        position=entry.vector("position", (2,)),
        width=entry.number("width", 0.44),
        yaw=entry.number("yaw", 0.0),
        rows=tuple(rows),
        keep_clear_x=_range(clear, "x"),
        keep_clear_y=_range(clear, "y"),
        spacing=_spacing(entry),
        start_open=_probability(opening, "probability", 0.0),
        open_distance=distance,
    )


def parse_recipe(data: Any, source: str = "<memory>") -> Recipe:
    """Validates a recipe given as parsed YAML/JSON data; raises :class:`RecipeFileError`."""
    entry = Reader(source, "recipe", data, _FIELDS, RecipeFileError)
    robot = entry.string("robot", "panda")
    if robot not in VALID_ROBOTS:
        entry.fail(f"unknown robot {robot!r}; valid robots: {', '.join(VALID_ROBOTS)}")
    region = Reader(source, "region", entry.required("region"), {"x", "y", "reach"}, RecipeFileError)
    receptacles = Reader(
        source, "receptacles", entry.required("receptacles"), {"count", "types", "at_most_one"}, RecipeFileError
    )
    receptacle_types = _types(receptacles, receptacles.required("types"), "receptacles.types")
    library = object_types()
    for name in receptacle_types:
        if not library[name].container or library[name].interior is None:
            receptacles.fail(f"{name!r} holds nothing; receptacles are plates, saucers, bowls and baskets")
    large = receptacles.data.get("at_most_one", [])
    at_most_one = frozenset(_types(receptacles, large, "receptacles.at_most_one") if large else ())
    objects = Reader(
        source,
        "objects",
        entry.required("objects"),
        {"count", "types", "exclude", "max_height", "match_colour", "start_in_receptacle"},
        RecipeFileError,
    )
    chosen = objects.required("types")
    if chosen == "pickable":
        chosen = [n for n, t in library.items() if t.pickable]
    names = _types(objects, chosen, "objects.types")
    excluded = set(_types(objects, objects.data["exclude"], "objects.exclude")) if "exclude" in objects.data else set()
    max_height = objects.number("max_height", 1.0)
    names = tuple(n for n in names if n not in excluded and library[n].size[2] <= max_height)
    if not names:
        objects.fail("no object type is left after 'exclude' and 'max_height'")
    for name in names:
        if not library[name].pickable:
            objects.fail(f"{name!r} is a receptacle, which no grasp tool takes; list it under receptacles")
    randomize = entry.data.get("randomize", {})
    Reader(source, "randomize", randomize, {"position", "yaw"}, RecipeFileError)
    return Recipe(
        name=entry.string("recipe"),
        source=source,
        description=entry.text("description"),
        robot=robot,
        cabinet=_parse_cabinet(source, entry.data.get("cabinet")),
        region_x=_range(region, "x"),
        region_y=_range(region, "y"),
        reach=_range(region, "reach"),
        spacing=_spacing(entry),
        receptacle_count=_count(receptacles),
        receptacle_types=receptacle_types,
        at_most_one=at_most_one,
        object_count=_count(objects),
        object_types=names,
        match_colour=_probability(objects, "match_colour", 0.0),
        start_in_receptacle=_probability(objects, "start_in_receptacle", 0.0),
        yaw_deg=entry.number("yaw", 180.0),
        randomize=dict(randomize),
    )


RECIPES = PackagedFiles("generate", "recipe")


def recipe_names() -> list[str]:
    """The packaged recipes."""
    return RECIPES.names()


def load_recipe(name_or_path: str = DEFAULT_RECIPE) -> Recipe:
    """A packaged recipe by name, or any recipe file by path."""
    path = RECIPES.path(name_or_path)
    return parse_recipe(read_data_file(path, RecipeFileError), str(path))
