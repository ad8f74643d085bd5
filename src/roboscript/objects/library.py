"""The object library: procedurally built household objects with real-world sizes, colours and masses.

YCB and Google Scanned Objects meshes cannot be installed from the package registries, so every object here is a
composite of convex parts shaped like its real counterpart. Sizes follow the YCB set where one exists. Each type has
a category (what a detector would call it) and a colour (what a scene description says of it).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from roboscript.errors import did_you_mean
from roboscript.objects import designs as shapes
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


_LIBRARY: dict[str, ObjectType] = {}


def _register(obj: ObjectType) -> ObjectType:
    if obj.name in _LIBRARY:
        raise ValueError(f"object type {obj.name!r} registered twice")
    _LIBRARY[obj.name] = obj
    return obj


# ---------------------------------------------------------------------------------------------------------------
# The catalogue. Densities in kg/m^3 of the solid parts: fruit ~ 850-950, wood ~ 600, ceramic ~ 2000 (walls),
# cardboard boxes ~ 300-500 (they are mostly air), plastic ~ 1000.

for _name, _category, _color, _parts, _density, _desc in [
    ("apple", "apple", "red", shapes.sphere(0.038), 850, "a red apple, 7.6 cm"),
    ("green_apple", "apple", "green", shapes.sphere(0.036), 850, "a green apple, 7.2 cm"),
    ("orange", "orange", "orange", shapes.sphere(0.036), 900, "an orange, 7.2 cm"),
    ("lemon", "lemon", "yellow", shapes.ellipsoid(0.034, 0.026, 0.026), 900, "a lemon, 6.8 cm long"),
    ("lime", "lime", "green", shapes.ellipsoid(0.028, 0.024, 0.024), 900, "a lime, 5.6 cm long"),
    ("plum", "plum", "purple", shapes.sphere(0.026), 950, "a plum, 5.2 cm"),
    ("peach", "peach", "peach", shapes.sphere(0.033), 900, "a peach, 6.6 cm"),
    ("strawberry", "strawberry", "red", shapes.ellipsoid(0.018, 0.018, 0.022), 900, "a strawberry, 4.4 cm tall"),
    ("tennis_ball", "tennis ball", "light_green", shapes.sphere(0.033), 270, "a tennis ball, 6.6 cm, 58 g"),
    ("baseball", "baseball", "white", shapes.sphere(0.037), 690, "a baseball, 7.4 cm, 145 g"),
    ("golf_ball", "golf ball", "white", shapes.sphere(0.021), 1150, "a golf ball, 4.3 cm"),
    ("softball", "softball", "yellow", shapes.sphere(0.048), 420, "a softball, 9.6 cm"),
]:
    shade = "light_green" if _name == "green_apple" else ""  # green as its name says, drawn a lighter green
    _register(ObjectType(_name, _category, _color, _parts, _density, _desc, round=True, shape="round", shade=shade))

_register(ObjectType("banana", "banana", "yellow", shapes.banana(), 900, "a banana, 20 cm long", shape="elongated"))
_register(ObjectType("pear", "pear", "light_green", shapes.pear(), 900, "a pear, 10 cm tall", shape="irregular"))

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
    ("brown_box", "brown", (0.072, 0.07, 0.055), 350, "a brown cosmetics carton, 7.2 x 7 x 5.5 cm"),
]:
    _register(ObjectType(_name, "box", _color, shapes.box(*_dims), _density, _desc, shape="box"))
_register(
    ObjectType(
        "white_and_pink_box",
        "box",
        "white",
        shapes.two_tone_box(0.095, 0.06, 0.05, 0.015, COLORS["pink"]),
        350,
        "a white supplement carton with a pink band, 9.5 x 6 x 5 cm",
        shape="box",
    )
)

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
    _register(ObjectType(_name, _cat, _color, shapes.box(*_dims), _density, _desc, shape="box"))

# Cans and bottles.
_register(
    ObjectType(
        "soup_can",
        "can",
        "red",
        shapes.cylinder(0.033, 0.101),
        700,
        "a tomato soup can, 6.6 x 10.1 cm",
        shape="cylinder",
    )
)
_register(
    ObjectType(
        "tuna_can", "can", "blue", shapes.cylinder(0.043, 0.034), 800, "a tuna can, 8.6 x 3.4 cm", shape="cylinder"
    )
)
for _name, _color, _cap, _r, _h, _desc in [
    ("medication_bottle", "orange", "white", 0.02, 0.08, "an orange medication bottle, 4 x 8 cm"),
    ("white_medication_bottle", "white", "blue", 0.022, 0.085, "a white medication bottle, 4.4 x 8.5 cm"),
    ("brown_medication_bottle", "brown", "white", 0.021, 0.08, "an amber medication bottle, 4.2 x 8 cm"),
]:
    _register(ObjectType(_name, "bottle", _color, shapes.bottle(_r, _h, COLORS[_cap]), 500, _desc, shape="cylinder"))

_register(
    ObjectType(
        "mustard_bottle",
        "bottle",
        "yellow",
        shapes.flat_bottle(0.095, 0.058, 0.19, 0.014, COLORS["red"]),
        450,
        "a yellow mustard bottle, 9.5 x 5.8 x 19 cm",
        shape="bottle",
    )
)
_register(
    ObjectType(
        "bleach_cleanser",
        "bottle",
        "white",
        shapes.flat_bottle(0.1, 0.067, 0.25, 0.017, COLORS["blue"]),
        450,
        "a white bleach cleanser bottle with a blue cap, 10 x 6.7 x 25 cm",
        shape="bottle",
    )
)

# Mugs and cups (containers, ceramic or plastic walls).
for _color in ("white", "red", "blue", "brown", "yellow", "green"):
    _register(
        ObjectType(
            f"{_color}_mug",
            "mug",
            _color,
            shapes.mug(0.04, 0.095),
            1800,
            f"a {_color} ceramic mug with a handle, 8 cm wide, 9.5 cm tall",
            shape="mug",
            container=True,
            interior=shapes.interior_of_cylinder(0.034, 0.008, 0.087),
        )
    )
for _color in ("brown", "blue", "white", "green", "red"):
    _register(
        ObjectType(
            f"{_color}_cup",
            "cup",
            _color,
            shapes.cup(0.028, 0.038, 0.09),
            1100,
            f"a {_color} plastic cup, 7.6 cm at the rim, 9 cm tall",
            shape="cup",
            container=True,
            interior=shapes.interior_of_cylinder(0.028, 0.006, 0.084),
        )
    )

_register(
    ObjectType(
        "white_and_yellow_mug",
        "mug",
        "white",
        shapes.mug(0.04, 0.095, accent=COLORS["yellow"]),
        1800,
        "a white ceramic mug, yellow inside and on its handle, 8 cm wide, 9.5 cm tall",
        shape="mug",
        container=True,
        interior=shapes.interior_of_cylinder(0.034, 0.008, 0.087),
    )
)
_register(
    ObjectType(
        "white_porcelain_mug",
        "mug",
        "white",
        shapes.mug(0.04, 0.095),
        2000,
        "a white porcelain coffee mug with a handle, 8 cm wide, 9.5 cm tall",
        shape="mug",
        container=True,
        interior=shapes.interior_of_cylinder(0.034, 0.008, 0.087),
    )
)
_register(
    ObjectType(
        "brown_ceramic_cup",
        "cup",
        "brown",
        shapes.cup(0.028, 0.038, 0.09),
        1500,
        "a brown ceramic cup without a handle, 7.6 cm at the rim, 9 cm tall",
        shape="cup",
        container=True,
        interior=shapes.interior_of_cylinder(0.028, 0.006, 0.084),
    )
)

# Plates, saucers, bowls, the footed bowl and the basket.
for _color in ("white", "blue", "red", "green", "yellow"):
    _register(
        ObjectType(
            f"{_color}_plate",
            "plate",
            _color,
            shapes.plate(0.11),
            1800,
            f"a {_color} plate, 22 cm across",
            shape="flat",
            container=True,
            interior=((-0.08, -0.08, 0.008), (0.08, 0.08, 0.1)),
            round_floor=True,
        )
    )
_register(
    ObjectType(
        "white_serving_plate",
        "plate",
        "white",
        shapes.plate(0.16, rim=0.026),
        1800,
        "a large white serving plate, 32 cm across",
        shape="flat",
        container=True,
        interior=((-0.12, -0.12, 0.008), (0.12, 0.12, 0.1)),
        round_floor=True,
    )
)
_register(
    ObjectType(
        "white_ceramic_plate",
        "plate",
        "white",
        shapes.square_plate(0.265, 0.22, 0.012),
        2000,
        "a white porcelain dinner plate with a square rim, 26.5 cm square",
        shape="flat",
        container=True,
        interior=((-0.11, -0.11, 0.008), (0.11, 0.11, 0.1)),
    )
)
_register(
    ObjectType(
        "turquoise_salad_plate",
        "plate",
        "turquoise",
        shapes.plate(0.105, rim=0.02),
        1800,
        "a turquoise salad plate, 21 cm across",
        shape="flat",
        container=True,
        interior=((-0.075, -0.075, 0.008), (0.075, 0.075, 0.1)),
        round_floor=True,
    )
)
_register(
    ObjectType(
        "green_plant_plate",
        "plate",
        "green",
        shapes.plate(0.1, rim=0.02, rim_height=0.02),
        1200,
        "an avocado-green plant saucer plate, 20 cm across",
        shape="flat",
        container=True,
        interior=((-0.07, -0.07, 0.008), (0.07, 0.07, 0.1)),
        round_floor=True,
    )
)
_register(
    ObjectType(
        "red_plant_saucer",
        "saucer",
        "red",
        shapes.square_saucer(0.19, 0.025, 0.006),
        1200,
        "a coral-red square plant saucer, 19 cm square, 2.5 cm deep",
        shape="flat",
        container=True,
        interior=((-0.088, -0.088, 0.006), (0.088, 0.088, 0.1)),
    )
)
for _color in ("white", "blue", "pink"):
    _register(
        ObjectType(
            f"{_color}_saucer",
            "saucer",
            _color,
            shapes.plate(0.075, rim=0.015, rim_height=0.012),
            1800,
            f"a {_color} saucer, 15 cm across",
            shape="flat",
            container=True,
            interior=((-0.05, -0.05, 0.008), (0.05, 0.05, 0.08)),
            round_floor=True,
        )
    )
for _color in ("white", "blue", "green", "red"):
    _register(
        ObjectType(
            f"{_color}_bowl",
            "bowl",
            _color,
            shapes.bowl(0.05, 0.085, 0.065),
            1800,
            f"a {_color} bowl, 17 cm across, 6.5 cm deep",
            shape="bowl",
            container=True,
            interior=((-0.055, -0.055, 0.008), (0.055, 0.055, 0.1)),
            round_floor=True,
        )
    )
_register(
    ObjectType(
        "red_plastic_bowl",
        "bowl",
        "red",
        shapes.bowl(0.04, 0.079, 0.053),
        1100,
        "a red plastic bowl, 16 cm across, 5.3 cm deep",
        shape="bowl",
        container=True,
        interior=((-0.05, -0.05, 0.008), (0.05, 0.05, 0.09)),
        round_floor=True,
    )
)
_register(
    ObjectType(
        "footed_bowl",
        "footed bowl",
        "sand",
        shapes.footed_bowl(),
        1800,
        "a sand-coloured footed bowl on a short stem, 19 cm across, 8.5 cm deep",
        shape="bowl",
        container=True,
        interior=((-0.06, -0.06, 0.058), (0.06, 0.06, 0.18)),
        round_floor=True,
    )
)
_register(
    ObjectType(
        "basket",
        "basket",
        "tan",
        shapes.basket(),
        500,
        "a woven basket, 34 x 26 x 13 cm",
        shape="basket",
        container=True,
        interior=((-0.16, -0.12, 0.008), (0.16, 0.12, 0.2)),
    )
)

_register(
    ObjectType(
        "basket_with_fabric_liner",
        "basket",
        "tan",
        shapes.lined_basket(0.28, 0.21, 0.13),
        500,
        "a small natural-finish basket with a fabric liner, 28 x 21 x 13 cm",
        shape="basket",
        container=True,
        interior=((-0.13, -0.095, 0.008), (0.13, 0.095, 0.2)),
    )
)

# Toys.
_register(
    ObjectType(
        "toy_bus",
        "toy bus",
        "yellow",
        shapes.toy_vehicle(0.14, 0.05, 0.06, 0.012, cabin=False),
        400,
        "a yellow toy bus, 14 cm long",
        shape="toy",
    )
)
_register(
    ObjectType(
        "toy_car",
        "toy car",
        "red",
        shapes.toy_vehicle(0.1, 0.045, 0.045, 0.011, cabin=True),
        400,
        "a red toy car, 10 cm long",
        shape="toy",
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
        close = did_you_mean(name, _LIBRARY, n=4)
        hint = f"; {close}" if close else f"; valid types: {', '.join(sorted(_LIBRARY))}"
        raise KeyError(f"unknown object type {name!r}{hint}") from None
