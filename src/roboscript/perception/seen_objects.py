"""The objects of the perception store: what one look found of each, moved along where the robot carried it, and
what is read off its points (its box, its footprint, a container's free inside)."""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from roboscript.geometry import Box3D, Transform, quat_from_yaw
from roboscript.objects import ObjectType, object_types
from roboscript.perception.base import Receptacle
from roboscript.perception.detection.grounding import normalize_phrase
from roboscript.perception.footprints import footprint_of
from roboscript.perception.reconstruction.instances import PIXEL_BLUR, Instance3D, footprint_points, object_box

STILL = 0.006  # metres from what an earlier look saw of an object within which a later look's points show it unmoved
STILL_SHARE = 0.97  # the share of a later look's points that must lie there
SHALLOW = 0.035  # metres: containers lower than this (plates, saucers) hold things on top, not inside
RIM = 0.02  # metres of a shallow container's edge that things should not rest on
SETTLE_INSET = 0.01  # metres: the footprint a let-go object falls within, shrunk by this; smaller drops are none


@dataclass
class SeenObject:
    """An object in the store: what one look found, moved along when the robot carried it."""

    name: str
    phrase: str
    points: np.ndarray
    normals: np.ndarray
    views: int  # in how many views it was found
    support: float  # height of the table it was seen above
    floor: float  # height of its underside (below its lowest point seen where it stands on the table)
    kind: ObjectType | None = None  # the library's idea of the phrase, for containers' interiors
    box: Box3D = field(init=False)

    def __post_init__(self) -> None:
        # Its points are depth pixels (observation's refinement, where it found enough), sharp down to the table.
        box = object_box(self.points, self.support, PIXEL_BLUR)
        self.box = Box3D(np.array([*box.lower[:2], min(box.lower[2], self.floor)]), box.upper)

    @property
    def outline(self) -> np.ndarray:
        """The points that show its outline from above."""
        return footprint_points(self.points, self.support)

    @cached_property
    def footprint(self) -> tuple[np.ndarray, float, np.ndarray]:
        """``(center_xy, yaw, half_extents_xy)`` of :attr:`outline` (:func:`footprint_of`); asked for by every
        placement's obstacles, so worked out once per object seen (a moved object is a new one)."""
        return footprint_of(self.outline)


def found_object(name: str, phrase: str, instance: Instance3D, support: float) -> SeenObject:
    """What a look found of ``phrase`` (``instance``, seen above a table at height ``support``), as ``name``."""
    views = sum(1 for b in instance.boxes if b != -1)
    floor = float(instance.box.lower[2])
    return SeenObject(name, phrase, instance.points, instance.normals, views, support, floor, library_type(phrase))


def part_of(fresh: SeenObject, before: SeenObject) -> bool:
    """Whether what ``fresh`` saw lies on what ``before`` saw (all but a few points within :data:`STILL` of its
    points): it has not moved since. A box pushed 2 cm shows a strip of its top where none was."""
    from scipy.spatial import cKDTree

    if len(fresh.points) == 0 or len(before.points) == 0:
        return False
    distance, _ = cKDTree(before.points).query(fresh.points, distance_upper_bound=STILL)
    return float(np.mean(np.isfinite(distance))) >= STILL_SHARE


def moved(obj: SeenObject, motion: Transform) -> SeenObject:
    """``obj`` as it is after the rigid ``motion`` (world frame); its support and underside rise and fall as its
    lowest point does."""
    points = motion.apply(obj.points)
    rise = float(points[:, 2].min() - obj.points[:, 2].min()) if len(points) else float(motion.position[2])
    return SeenObject(
        obj.name,
        obj.phrase,
        points,
        obj.normals @ motion.rotation.T,
        obj.views,
        obj.support + rise,
        obj.floor + rise,
        obj.kind,
    )


def fallen(obj: SeenObject, scene: np.ndarray) -> SeenObject:
    """``obj``, let go and not found again by the last look (what it lies in hid it, or the detector took it for
    part of that), where it has fallen: from above, what the cameras see within its footprint (``scene``, the
    look's surfaces) is its own top, so its top goes to the highest surface seen there, though not below what it
    stands on (the lowest seen)."""
    lower, upper = obj.box.lower, obj.box.upper
    xy = scene[:, :2]
    under = np.all((xy > lower[:2] + SETTLE_INSET) & (xy < upper[:2] - SETTLE_INSET), axis=1)
    below = scene[under & (scene[:, 2] < upper[2] + SETTLE_INSET), 2]
    if len(below) < 10:
        return obj
    low, high = np.percentile(below, [2, 98])
    drop = float(min(upper[2] - high, lower[2] - low))
    if drop <= SETTLE_INSET:
        return obj
    return moved(obj, Transform(np.array([0.0, 0.0, -drop]), np.array([0.0, 0.0, 0.0, 1.0])))


def object_name(phrase: str) -> str:
    """The store's name for what a phrase found (``red block`` -> ``red_block``)."""
    return phrase.replace(" ", "_")


def library_type(phrase: str) -> ObjectType | None:
    """The object type a phrase names (``footed bowl``, ``white plate``), or the first of a category it names."""
    types = object_types()
    key = object_name(phrase)
    if key in types:
        return types[key]
    for kind in types.values():
        if normalize_phrase(kind.category) == phrase or phrase.endswith(" " + normalize_phrase(kind.category)):
            return kind
    return None


def interior_of(points: np.ndarray, outline: np.ndarray, kind: ObjectType, name: str) -> Receptacle:
    """The free volume of a seen container, from the lowest point seen near its middle up. Across: a shallow
    one (a plate) holds what rests on it up to its rim, so its footprint less a rim; a deep one (a bowl, a
    basket) holds things inside its walls, so its footprint shrunk as the library's type of it is (a bowl's
    opening is about 60% of its width)."""
    center, yaw, half = footprint_of(outline)
    bottom = float(points[:, 2].min())
    frame = Transform(np.array([center[0], center[1], bottom]), quat_from_yaw(yaw))
    local = frame.inverse().apply(points)
    height = float(local[:, 2].max())
    (lx, ly, lz), (ux, uy, uz) = kind.interior
    bounds_lower, bounds_upper = (np.asarray(b, dtype=float) for b in kind.bounds)
    if height < SHALLOW:
        inner_half = np.maximum(half - RIM, half * 0.5)
    else:
        type_half = (bounds_upper[:2] - bounds_lower[:2]) / 2
        inner_half = half * float(np.min(np.array([(ux - lx) / 2, (uy - ly) / 2]) / type_half))
    middle = local[np.all(np.abs(local[:, :2]) < inner_half * 0.6, axis=1)]
    floor = float(middle[:, 2].min()) if len(middle) >= 5 else lz
    top = max(height + (uz - bounds_upper[2]), floor + 0.05)
    lower, upper = np.array([-inner_half[0], -inner_half[1], floor]), np.array([*inner_half, top])
    return Receptacle(name, frame, lower, upper, kind.round_floor)
