"""The object library: procedurally built household objects with real-world sizes, colours and masses.

YCB and Google Scanned Objects meshes cannot be installed from the package registries, so every object here is a
composite of convex parts shaped like its real counterpart. Sizes follow the YCB set where one exists. Each type has
a category (what a detector would call it) and a colour (what a scene description says of it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from roboscript.sim.shapes import RGBA, Part, arc_of_capsules, disk, open_box, parts_bounds, ring_wall

COLORS: dict[str, RGBA] = {
    "red": (0.78, 0.08, 0.08, 1.0),
    "dark_red": (0.5, 0.05, 0.08, 1.0),
    "green": (0.15, 0.6, 0.15, 1.0),
    "light_green": (0.55, 0.8, 0.25, 1.0),
    "blue": (0.12, 0.3, 0.8, 1.0),
    "yellow": (0.95, 0.85, 0.15, 1.0),
    "orange": (0.98, 0.55, 0.1, 1.0),
    "purple": (0.42, 0.12, 0.45, 1.0),
    "pink": (0.95, 0.6, 0.6, 1.0),
    "white": (0.93, 0.93, 0.91, 1.0),
    "black": (0.08, 0.08, 0.08, 1.0),
    "gray": (0.5, 0.5, 0.52, 1.0),
    "brown": (0.45, 0.28, 0.14, 1.0),
    "wood": (0.76, 0.6, 0.4, 1.0),
    "tan": (0.82, 0.7, 0.5, 1.0),
    "peach": (0.98, 0.7, 0.5, 1.0),
    "cyan": (0.1, 0.7, 0.8, 1.0),
}


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
    bounds: tuple[np.ndarray, np.ndarray] = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "bounds", parts_bounds(self.parts))

    @property
    def rgba(self) -> RGBA:
        return COLORS[self.color]

    @property
    def size(self) -> np.ndarray:
        """Extent of the axis-aligned bounding box in the object's frame, metres."""
        lower, upper = self.bounds
        return upper - lower

    @property
    def footprint_radius(self) -> float:
        lower, upper = self.bounds
        return float(np.max(np.linalg.norm([[lower[0], lower[1]], [upper[0], upper[1]]], axis=1)))


_LIBRARY: dict[str, ObjectType] = {}


def _register(obj: ObjectType) -> ObjectType:
    if obj.name in _LIBRARY:
        raise ValueError(f"object type {obj.name!r} registered twice")
    _LIBRARY[obj.name] = obj
    return obj


# ---------------------------------------------------------------------------------------------------------------
# Shape recipes. Every recipe returns parts in a frame whose origin is the centre of the object's bottom.


# Walls start this far above the base they stand on, so that only the base touches the table: a wall of 16 box
# segments resting on the table would add 64 contacts and cost a third of the simulation speed.
_WALL_LIFT = 0.002


def _sphere(radius: float) -> tuple[Part, ...]:
    return (Part("sphere", (radius,), (0.0, 0.0, radius)),)


def _ellipsoid(rx: float, ry: float, rz: float) -> tuple[Part, ...]:
    return (Part("ellipsoid", (rx, ry, rz), (0.0, 0.0, rz)),)


def _box(lx: float, ly: float, lz: float) -> tuple[Part, ...]:
    return (Part("box", (lx / 2, ly / 2, lz / 2), (0.0, 0.0, lz / 2)),)


def _cylinder(radius: float, height: float) -> tuple[Part, ...]:
    return (Part("cylinder", (radius, height / 2), (0.0, 0.0, height / 2)),)


def _banana() -> tuple[Part, ...]:
    # A curved chain of capsules lying on the table, about 19 cm long and 3.6 cm thick.
    thickness = 0.018
    arc = arc_of_capsules(0.16, thickness, math.radians(-125), math.radians(-55), 6, (0.0, 0.0, 0.0), "xy")
    # Lift so that the lowest point rests at z = 0; centre the arc on the origin in x, y.
    lower, upper = parts_bounds(arc)
    offset = np.array([-(lower[0] + upper[0]) / 2, -(lower[1] + upper[1]) / 2, thickness])
    tip = (0.35, 0.25, 0.1, 1.0)
    out = []
    for i, p in enumerate(arc):
        ends = i in (0, len(arc) - 1)
        # Like a real banana, it rests on its ends: the middle is lifted a little off the table, which also
        # halves its contacts with the table.
        lift = np.array([0.0, 0.0, 0.0 if ends else 0.0015])
        out.append(Part(p.kind, p.size, tuple(np.array(p.pos) + offset + lift), p.quat, tip if ends else None))
    return tuple(out)


def _pear() -> tuple[Part, ...]:
    return (
        Part("sphere", (0.034,), (0.0, 0.0, 0.034)),
        Part("sphere", (0.024,), (0.0, 0.0, 0.07)),
        Part("capsule", (0.003, 0.006), (0.0, 0.0, 0.098), rgba=COLORS["brown"]),
    )


def _mug(radius: float, height: float, wall: float = 0.006) -> tuple[Part, ...]:
    parts = [disk(radius, 0.008)]
    parts += ring_wall(radius - wall / 2, radius - wall / 2, height - _WALL_LIFT, wall, 16, z0=_WALL_LIFT)
    # The handle: a C of capsules on the +x side, in the x-z plane.
    handle_r = height * 0.3
    parts += arc_of_capsules(
        handle_r, 0.006, math.radians(-80), math.radians(80), 5, (radius - 0.004, 0.0, height * 0.52), "xz"
    )
    return tuple(parts)


def _cup(bottom_radius: float, top_radius: float, height: float, wall: float = 0.004) -> tuple[Part, ...]:
    return (
        disk(bottom_radius + wall / 2, 0.006),
        *ring_wall(bottom_radius, top_radius, height - _WALL_LIFT, wall, 14, z0=_WALL_LIFT),
    )


def _bowl(bottom_radius: float, top_radius: float, height: float, z0: float = 0.0) -> tuple[Part, ...]:
    return (
        disk(bottom_radius + 0.004, 0.008, z0),
        *ring_wall(bottom_radius, top_radius, height - _WALL_LIFT, 0.007, 16, z0 + _WALL_LIFT),
    )


def _footed_bowl() -> tuple[Part, ...]:
    foot = disk(0.045, 0.01)
    stem = Part("cylinder", (0.013, 0.02), (0.0, 0.0, 0.03))
    return (foot, stem, *_bowl(0.05, 0.095, 0.085, z0=0.05))


def _plate(radius: float, rim: float = 0.022, rim_height: float = 0.016) -> tuple[Part, ...]:
    inner = radius - rim
    # The rim starts near the top of the base: a steeply flared rim reaching down to the table would put every
    # segment's bounding box against the table top and into the narrow phase on every step.
    return (disk(inner + 0.004, 0.008), *ring_wall(inner, radius, rim_height - 0.004, 0.005, 16, z0=0.007))


def _basket() -> tuple[Part, ...]:
    return tuple(open_box(0.34, 0.26, 0.13, 0.008))


def _bottle(radius: float, height: float, cap_rgba: RGBA) -> tuple[Part, ...]:
    body_h = height * 0.78
    return (
        Part("cylinder", (radius, body_h / 2), (0.0, 0.0, body_h / 2)),
        Part("cylinder", (radius * 0.6, (height - body_h) * 0.3), (0.0, 0.0, body_h + (height - body_h) * 0.3)),
        Part(
            "cylinder",
            (radius * 0.75, (height - body_h) * 0.2),
            (0.0, 0.0, height - (height - body_h) * 0.2),
            rgba=cap_rgba,
        ),
    )


def _toy_vehicle(length: float, width: float, height: float, wheel_r: float, cabin: bool) -> tuple[Part, ...]:
    body_h = height - wheel_r
    parts = [
        Part(
            "box",
            (length / 2, width / 2, body_h / 2 * (0.6 if cabin else 1.0)),
            (0.0, 0.0, wheel_r + body_h / 2 * (0.6 if cabin else 1.0)),
        )
    ]
    if cabin:
        parts.append(
            Part(
                "box",
                (length * 0.3, width / 2 * 0.9, body_h * 0.2),
                (-length * 0.1, 0.0, wheel_r + body_h * 0.8),
                rgba=COLORS["cyan"],
            )
        )
    wheel_q = (math.sin(math.pi / 4), 0.0, 0.0, math.cos(math.pi / 4))  # axis along y
    for sx in (-1, 1):
        for sy in (-1, 1):
            parts.append(
                Part(
                    "cylinder",
                    (wheel_r, 0.006),
                    (sx * length * 0.32, sy * (width / 2 - 0.004), wheel_r),
                    wheel_q,
                    COLORS["black"],
                )
            )
    return tuple(parts)


def _interior_of_cylinder(radius: float, z0: float, height: float) -> tuple[tuple[float, ...], tuple[float, ...]]:
    r = radius / math.sqrt(2)
    return ((-r, -r, z0), (r, r, z0 + height))


# ---------------------------------------------------------------------------------------------------------------
# The catalogue. Densities in kg/m^3 of the solid parts: fruit ~ 850-950, wood ~ 600, ceramic ~ 2000 (walls),
# cardboard boxes ~ 300-500 (they are mostly air), plastic ~ 1000.

for _name, _category, _color, _parts, _density, _desc in [
    ("apple", "apple", "red", _sphere(0.038), 850, "a red apple, 7.6 cm"),
    ("green_apple", "apple", "light_green", _sphere(0.036), 850, "a green apple, 7.2 cm"),
    ("orange", "orange", "orange", _sphere(0.036), 900, "an orange, 7.2 cm"),
    ("lemon", "lemon", "yellow", _ellipsoid(0.034, 0.026, 0.026), 900, "a lemon, 6.8 cm long"),
    ("lime", "lime", "green", _ellipsoid(0.028, 0.024, 0.024), 900, "a lime, 5.6 cm long"),
    ("plum", "plum", "purple", _sphere(0.026), 950, "a plum, 5.2 cm"),
    ("peach", "peach", "peach", _sphere(0.033), 900, "a peach, 6.6 cm"),
    ("strawberry", "strawberry", "red", _ellipsoid(0.018, 0.018, 0.022), 900, "a strawberry, 4.4 cm tall"),
    ("tennis_ball", "tennis ball", "light_green", _sphere(0.033), 270, "a tennis ball, 6.6 cm, 58 g"),
    ("baseball", "baseball", "white", _sphere(0.037), 690, "a baseball, 7.4 cm, 145 g"),
    ("golf_ball", "golf ball", "white", _sphere(0.021), 1150, "a golf ball, 4.3 cm"),
    ("softball", "softball", "yellow", _sphere(0.048), 420, "a softball, 9.6 cm"),
]:
    _register(ObjectType(_name, _category, _color, _parts, _density, _desc, round=True))

_register(ObjectType("banana", "banana", "yellow", _banana(), 900, "a banana, 19 cm long"))
_register(ObjectType("pear", "pear", "light_green", _pear(), 900, "a pear, 10 cm tall"))

# Boxes (cardboard packaging, sizes of the YCB food boxes, scaled to fit a drawer lying down).
for _name, _color, _dims, _density, _desc in [
    ("cracker_box", "red", (0.16, 0.06, 0.21), 200, "a red cracker box, 16 x 6 x 21 cm"),
    ("sugar_box", "yellow", (0.09, 0.038, 0.175), 350, "a yellow sugar box, 9 x 3.8 x 17.5 cm"),
    ("pudding_box", "brown", (0.11, 0.089, 0.035), 500, "a brown pudding box, 11 x 8.9 x 3.5 cm"),
    ("gelatin_box", "red", (0.089, 0.073, 0.028), 500, "a red gelatin box, 8.9 x 7.3 x 2.8 cm"),
    ("tea_box", "green", (0.12, 0.07, 0.06), 250, "a green tea box, 12 x 7 x 6 cm"),
    ("cereal_box", "blue", (0.12, 0.05, 0.16), 200, "a small blue cereal box, 12 x 5 x 16 cm"),
    ("blue_box", "blue", (0.08, 0.06, 0.05), 400, "a small blue box, 8 x 6 x 5 cm"),
    ("red_box", "red", (0.07, 0.07, 0.05), 400, "a small red box, 7 x 7 x 5 cm"),
    ("yellow_box", "yellow", (0.09, 0.05, 0.045), 400, "a small yellow box, 9 x 5 x 4.5 cm"),
]:
    _register(ObjectType(_name, "box", _color, _box(*_dims), _density, _desc))

# Blocks and cubes.
for _name, _color, _dims, _density, _desc, _cat in [
    ("wooden_block", "wood", (0.05, 0.05, 0.05), 600, "a 5 cm wooden cube", "block"),
    ("red_block", "red", (0.05, 0.05, 0.05), 600, "a 5 cm red wooden cube", "block"),
    ("blue_block", "blue", (0.05, 0.05, 0.05), 600, "a 5 cm blue wooden cube", "block"),
    ("green_block", "green", (0.05, 0.05, 0.05), 600, "a 5 cm green wooden cube", "block"),
    ("wooden_bar", "wood", (0.1, 0.04, 0.04), 600, "a 10 x 4 x 4 cm wooden bar", "block"),
    ("rubiks_cube", "white", (0.057, 0.057, 0.057), 550, "a Rubik's cube, 5.7 cm", "cube"),
    ("sponge", "yellow", (0.09, 0.06, 0.03), 80, "a kitchen sponge, 9 x 6 x 3 cm", "sponge"),
]:
    _register(ObjectType(_name, _cat, _color, _box(*_dims), _density, _desc))

# Cans and bottles.
_register(ObjectType("soup_can", "can", "red", _cylinder(0.033, 0.101), 700, "a tomato soup can, 6.6 x 10.1 cm"))
_register(ObjectType("tuna_can", "can", "blue", _cylinder(0.043, 0.034), 800, "a tuna can, 8.6 x 3.4 cm"))
for _name, _color, _cap, _r, _h, _desc in [
    ("medication_bottle", "orange", "white", 0.02, 0.08, "an orange medication bottle, 4 x 8 cm"),
    ("white_medication_bottle", "white", "blue", 0.022, 0.085, "a white medication bottle, 4.4 x 8.5 cm"),
    ("mustard_bottle", "yellow", "red", 0.03, 0.15, "a yellow mustard bottle, 6 x 15 cm"),
]:
    _register(ObjectType(_name, "bottle", _color, _bottle(_r, _h, COLORS[_cap]), 500, _desc))

# Mugs and cups (containers, ceramic or plastic walls).
for _color in ("white", "red", "blue", "brown", "yellow", "green"):
    _register(
        ObjectType(
            f"{_color}_mug",
            "mug",
            _color,
            _mug(0.04, 0.095),
            1800,
            f"a {_color} ceramic mug with a handle, 8 cm wide, 9.5 cm tall",
            container=True,
            interior=_interior_of_cylinder(0.034, 0.008, 0.087),
        )
    )
for _color in ("brown", "blue", "white", "green", "red"):
    _register(
        ObjectType(
            f"{_color}_cup",
            "cup",
            _color,
            _cup(0.028, 0.038, 0.09),
            1100,
            f"a {_color} plastic cup, 7.6 cm at the rim, 9 cm tall",
            container=True,
            interior=_interior_of_cylinder(0.028, 0.006, 0.084),
        )
    )

# Plates, saucers, bowls, the footed bowl and the basket.
for _color in ("white", "blue", "red", "green", "yellow"):
    _register(
        ObjectType(
            f"{_color}_plate",
            "plate",
            _color,
            _plate(0.11),
            1800,
            f"a {_color} plate, 22 cm across",
            container=True,
            interior=((-0.08, -0.08, 0.008), (0.08, 0.08, 0.1)),
        )
    )
_register(
    ObjectType(
        "white_serving_plate",
        "plate",
        "white",
        _plate(0.16, rim=0.026),
        1800,
        "a large white serving plate, 32 cm across",
        container=True,
        interior=((-0.12, -0.12, 0.008), (0.12, 0.12, 0.1)),
    )
)
for _color in ("white", "blue", "pink"):
    _register(
        ObjectType(
            f"{_color}_saucer",
            "saucer",
            _color,
            _plate(0.075, rim=0.015, rim_height=0.012),
            1800,
            f"a {_color} saucer, 15 cm across",
            container=True,
            interior=((-0.05, -0.05, 0.008), (0.05, 0.05, 0.08)),
        )
    )
for _color in ("white", "blue", "green", "red"):
    _register(
        ObjectType(
            f"{_color}_bowl",
            "bowl",
            _color,
            _bowl(0.05, 0.085, 0.065),
            1800,
            f"a {_color} bowl, 17 cm across, 6.5 cm deep",
            container=True,
            interior=((-0.055, -0.055, 0.008), (0.055, 0.055, 0.1)),
        )
    )
_register(
    ObjectType(
        "footed_bowl",
        "footed bowl",
        "white",
        _footed_bowl(),
        1800,
        "a white footed bowl on a short stem, 19 cm across, 8.5 cm deep",
        container=True,
        interior=((-0.06, -0.06, 0.058), (0.06, 0.06, 0.18)),
    )
)
_register(
    ObjectType(
        "basket",
        "basket",
        "tan",
        _basket(),
        500,
        "a woven basket, 34 x 26 x 13 cm",
        container=True,
        interior=((-0.16, -0.12, 0.008), (0.16, 0.12, 0.2)),
    )
)

# Toys.
_register(
    ObjectType(
        "toy_bus",
        "toy bus",
        "yellow",
        _toy_vehicle(0.14, 0.05, 0.06, 0.012, cabin=False),
        400,
        "a yellow toy bus, 14 cm long",
    )
)
_register(
    ObjectType(
        "toy_car",
        "toy car",
        "red",
        _toy_vehicle(0.1, 0.045, 0.045, 0.011, cabin=True),
        400,
        "a red toy car, 10 cm long",
    )
)


def object_types() -> dict[str, ObjectType]:
    """Every registered object type by name."""
    return dict(_LIBRARY)


def get_object_type(name: str) -> ObjectType:
    """The object type ``name``; raises ``KeyError`` listing the closest valid names."""
    try:
        return _LIBRARY[name]
    except KeyError:
        import difflib

        close = difflib.get_close_matches(name, _LIBRARY, n=4, cutoff=0.5)
        hint = f"; did you mean {', '.join(close)}?" if close else f"; valid types: {', '.join(sorted(_LIBRARY))}"
        raise KeyError(f"unknown object type {name!r}{hint}") from None
