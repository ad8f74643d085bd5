"""The object library: household objects with real-world sizes, colours and masses, as ``catalogue.yaml`` lists
them, each built of convex parts by a recipe of :mod:`roboscript.objects.designs`. Each type has a category (what a
detector would call it) and a colour (what a scene description says of it).
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass, field
from functools import cache
from importlib import resources

import numpy as np

from roboscript.datafile import DataFileError, Reader, entry_label, read_data_file
from roboscript.errors import UnknownNameError, unknown_name
from roboscript.objects import designs
from roboscript.objects.designs import COLORS
from roboscript.objects.shapes import RGBA, Part, parts_bounds

# Shape classes, for studies of how shape decides success: balls and fruit, boxes and blocks, cans and round
# bottles, flat bottles, mugs (a handle), cups, long things, irregular ones, toy vehicles, and the receptacles.
SHAPES = ("round", "box", "cylinder", "bottle", "mug", "cup", "elongated", "irregular", "toy", "flat", "bowl", "basket")
RECEPTACLE_CATEGORIES = frozenset({"plate", "saucer", "bowl", "footed bowl", "basket"})


@dataclass(frozen=True)
class ObjectType:
    """A kind of object that world files can place, e.g. ``apple`` or ``white_mug``.

    ``container`` objects hold other objects; ``interior`` is the box (in the object's frame) where held things
    go, as ``(lower, upper)``.
    """

    name: str
    category: str
    color: str
    parts: tuple[Part, ...]
    density: float
    description: str
    container: bool = False
    interior: tuple[tuple[float, float, float], tuple[float, float, float]] | None = None
    friction: float = 1.0
    round: bool = False  # rolls: given rolling friction so it settles like a real, not quite round, fruit
    # The interior's floor is round (a plate's, a bowl's): the disc inscribed in ``interior``'s box. Beyond it, in
    # the box's corners, a thing would stand on the rim or against the wall, tilted.
    round_floor: bool = False
    # The shape class the object-shape study groups by (SHAPES); set for every type.
    shape: str = ""
    # The colour it is drawn in where that differs from the one its name says (a green apple of a lighter green).
    shade: str = ""
    bounds: tuple[np.ndarray, np.ndarray] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.shape not in SHAPES:
            raise ValueError(f"object type {self.name!r}: shape {self.shape!r} is not one of {', '.join(SHAPES)}")
        object.__setattr__(self, "bounds", parts_bounds(self.parts))

    @property
    def pickable(self) -> bool:
        """Whether tasks pick it up: everything but the receptacles (plates, saucers, bowls, baskets), which things
        are put in or on and which no grasp tool takes (a rim pinch is not among the grasps)."""
        return self.category not in RECEPTACLE_CATEGORIES

    @property
    def appearance(self) -> str:
        """The colour it is drawn in (a key of COLORS)."""
        return self.shade or self.color

    @property
    def rgba(self) -> RGBA:
        return COLORS[self.appearance]

    @property
    def size(self) -> np.ndarray:
        """Extent of the axis-aligned bounding box in the object's frame, metres."""
        lower, upper = self.bounds
        return upper - lower

    @property
    def footprint_radius(self) -> float:
        lower, upper = self.bounds
        return float(np.max(np.linalg.norm([[lower[0], lower[1]], [upper[0], upper[1]]], axis=1)))


OBJECT_LISTING = "`roboscript objects` lists them"  # what a refusal of an object type's name says of the valid ones


class CatalogueFileError(DataFileError):
    kind = "object catalogue"


# The recipes a catalogue entry's design may name: the public part builders of the designs module.
DESIGNS = {
    name: fn
    for name, fn in vars(designs).items()
    if inspect.isfunction(fn)
    and fn.__module__ == designs.__name__
    and not name.startswith("_")
    and name != "interior_of_cylinder"
}
FIELDS = {
    "name",
    "category",
    "color",
    "shade",
    "shape",
    "design",
    "density",
    "description",
    "round",
    "friction",
    "container",
    "interior",
    "round_floor",
}


@cache
def _library() -> dict[str, ObjectType]:
    return read_catalogue(str(resources.files("roboscript.objects") / "catalogue.yaml"))


def read_catalogue(path: str) -> dict[str, ObjectType]:
    """The object types of the catalogue file ``path`` by name, each checked; raises :class:`CatalogueFileError`
    naming the entry and the field where one is wrong."""
    entries = read_data_file(path, CatalogueFileError)
    if not isinstance(entries, list):
        raise CatalogueFileError(path, "top level", f"expected a list of object types, got {type(entries).__name__}")
    library: dict[str, ObjectType] = {}
    for index, data in enumerate(entries):
        kind = _object_type(Reader(path, entry_label("catalogue", index, data), data, FIELDS, CatalogueFileError))
        if kind.name in library:
            raise CatalogueFileError(path, entry_label("catalogue", index, data), f"{kind.name!r} is listed twice")
        library[kind.name] = kind
    return library


def _object_type(entry: Reader) -> ObjectType:
    color, shade = entry.string("color"), entry.text("shade")
    for word in (color, shade or color):
        if word not in COLORS:
            entry.fail(f"colour {word!r} is not one of {', '.join(COLORS)}")
    if entry.string("shape") not in SHAPES:
        entry.fail(f"shape {entry.data['shape']!r} is not one of {', '.join(SHAPES)}")
    flags = {key: entry.data.get(key, False) for key in ("round", "container", "round_floor")}
    for key, value in flags.items():
        if not isinstance(value, bool):
            entry.fail(f"field {key!r} must be true or false, got {value!r}")
    try:
        return ObjectType(
            entry.string("name"),
            entry.string("category"),
            color,
            _parts(entry),
            entry.number("density"),
            entry.string("description"),
            container=flags["container"],
            interior=_interior(entry) if "interior" in entry.data else None,
            friction=entry.number("friction", 1.0),
            round=flags["round"],
            round_floor=flags["round_floor"],
            shape=entry.string("shape"),
            shade=shade,
        )
    except ValueError as exc:
        entry.fail(str(exc))


def _parts(entry: Reader) -> tuple[Part, ...]:
    """The parts of the entry's design: its recipe called with its parameters (colour names made colours)."""
    design = entry.required("design")
    if not isinstance(design, dict) or design.get("kind") not in DESIGNS:
        kind = design.get("kind") if isinstance(design, dict) else design
        entry.fail(f"design kind {kind!r} is not one of {', '.join(sorted(DESIGNS))}")
    recipe = DESIGNS[design["kind"]]
    parameters = inspect.signature(recipe).parameters
    arguments = {k: v for k, v in design.items() if k != "kind"}
    unknown = sorted(set(arguments) - set(parameters))
    missing = [p for p, spec in parameters.items() if spec.default is inspect.Parameter.empty and p not in arguments]
    if unknown or missing:
        entry.fail(
            f"design {design['kind']!r} takes {', '.join(parameters) or 'no parameters'}"
            + (f"; unknown: {', '.join(unknown)}" if unknown else "")
            + (f"; missing: {', '.join(missing)}" if missing else "")
        )
    for key, value in arguments.items():
        if "rgba" in key or key == "accent":
            if value not in COLORS:
                entry.fail(f"design parameter {key!r}: colour {value!r} is not one of {', '.join(COLORS)}")
            arguments[key] = COLORS[value]
        elif not isinstance(value, int | float):
            entry.fail(f"design parameter {key!r} must be a number, got {value!r}")
    return recipe(**arguments)


def _interior(entry: Reader) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Where held things go: ``{box: [lower, upper]}``, or the box inscribed in ``{cylinder: {radius, z0,
    height}}``."""
    interior = entry.data["interior"]
    if isinstance(interior, dict) and set(interior) == {"box"}:
        box = Reader(
            entry.source,
            entry.entry,
            {"lower": interior["box"][0], "upper": interior["box"][1]}
            if isinstance(interior["box"], list) and len(interior["box"]) == 2
            else {},
            {"lower", "upper"},
            entry.error,
        )
        return box.vector("lower", (3,)), box.vector("upper", (3,))
    if isinstance(interior, dict) and set(interior) == {"cylinder"} and isinstance(interior["cylinder"], dict):
        cylinder = Reader(entry.source, entry.entry, interior["cylinder"], {"radius", "z0", "height"}, entry.error)
        return designs.interior_of_cylinder(cylinder.number("radius"), cylinder.number("z0"), cylinder.number("height"))
    entry.fail(f"interior must be {{box: [lower, upper]}} or {{cylinder: {{radius, z0, height}}}}, got {interior!r}")


def object_types() -> dict[str, ObjectType]:
    """Every object type of the catalogue by name."""
    return dict(_library())


def get_object_type(name: str) -> ObjectType:
    """The object type ``name``; raises ``KeyError`` listing the closest valid names."""
    library = _library()
    try:
        return library[name]
    except KeyError:
        listing = f"valid types: {', '.join(sorted(library))}"
        raise UnknownNameError(unknown_name("object type", name, library, listing, n=4)) from None
