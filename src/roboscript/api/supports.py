"""What a held object put down rests on: a container's or an open drawer's interior, the flat top of another
object (stacking) or of the furniture, or the table, as perception sees them.

Any object with a flat top holds things on it: "put the red block on the gelatin box" means on its top face,
whether or not the box is a container. Whether a top is flat is read from the observed points, not from a list of
kinds: the points within :data:`FLAT_TOP_BAND` of the top must spread over :data:`FLAT_TOP_SHARE` of the box's
footprint (a box's top does; a ball's cap does not).
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.api.nearby import Support
from roboscript.api.spots import Footprint
from roboscript.geometry import Transform, quat_from_yaw
from roboscript.names import TABLE, kind_of
from roboscript.perception.base import Perception, Receptacle, UnknownObjectError

FLAT_TOP_BAND = 0.004  # metres below an object's top where its top face's points lie
FLAT_TOP_SHARE = 0.3  # of its footprint's area the top face's points must span
FLAT_TOP_POINTS = 5  # fewer points there: too little seen to tell
HEADROOM = 0.4  # metres above a top face counted as its free volume
DOOR_OPEN_ENOUGH = math.radians(40)  # a door opened less than this closes its compartment (the benchmark's "open")
CLOSED_DRAWER = 0.04  # metres: a drawer's reachable interior shorter than this is closed
FLAT_RIM = 0.03  # metres: a receptacle whose rim stands less than this above its floor is a plate or a saucer
PLATE_EDGE = 0.015  # metres kept inside a plate's outline by what is set down on it (its rim rises there)
RESTS_ON = 0.03  # metres a thing's bottom may stand off a surface it rests on (a plate's rim, a sagging liner)
UNDER_SLACK = 0.005  # metres a floor may stand above a thing's bottom and still bear it (perceived heights)
# Metres an inside as last measured may grow by when looked at again: the arm that pulled a drawer hid up to 5 cm of
# its depth from the look before.
INSIDE_SLACK = 0.1


def top_face(perception: Perception, name: str) -> Receptacle | None:
    """The flat top of ``name`` as a receptacle (its footprint, at the top's height), or None where the top is
    not flat (a ball, a banana) or too little of it was seen."""
    box = perception.box(name)
    points = perception.points(name).points
    band = points[points[:, 2] > box.upper[2] - FLAT_TOP_BAND] if len(points) else points
    if len(band) < FLAT_TOP_POINTS:
        return None
    spread = np.ptp(band[:, :2], axis=0)
    if float(np.prod(spread)) < FLAT_TOP_SHARE * float(np.prod(box.size[:2])):
        return None
    center, yaw, half = perception.footprint(name)
    frame = Transform(np.array([center[0], center[1], box.upper[2]]), quat_from_yaw(float(yaw)))
    half = np.asarray(half, dtype=float)
    return Receptacle(name, frame, np.array([-half[0], -half[1], 0.0]), np.array([half[0], half[1], HEADROOM]))


def table_top(perception: Perception) -> Receptacle:
    """The whole top of the table (reach is the motion planner's to judge)."""
    table = perception.box(TABLE)
    top = float(table.upper[2])
    return Receptacle(
        TABLE, Transform.identity(), np.array([*table.lower[:2], top]), np.array([*table.upper[:2], top + HEADROOM])
    )


def holds(perception: Perception, name: str) -> Receptacle | None:
    """What ``name`` holds things in or on: its interior (a bowl, a plate, an open drawer) or else its flat top;
    None where it has neither or perception cannot tell."""
    receptacle = holds_interior(perception, name)
    if receptacle is not None:
        return receptacle
    if kind_of(name) in ("drawer", "handle", "door"):
        return None
    return top_face(perception, name)


def whole_surface(perception: Perception, receptacle: Receptacle) -> Receptacle | None:
    """A plate's or a saucer's whole top, up to :data:`PLATE_EDGE` from its outline, where its flat middle
    (``receptacle``) is smaller: things set down on a plate may rest partly on its rim, as on a real plate (an
    apple beside a banana on a 26 cm plate). None for anything with walls."""
    if kind_of(receptacle.name) in ("drawer", "door", "handle") or receptacle.name == TABLE:
        return None
    box = perception.box(receptacle.name)
    if box.upper[2] - floor_of(receptacle) >= FLAT_RIM:
        return None
    center, yaw, half = perception.footprint(receptacle.name)
    frame = Transform(np.array([center[0], center[1], receptacle.frame.position[2]]), quat_from_yaw(float(yaw)))
    reach = np.maximum(np.asarray(half, dtype=float) - PLATE_EDGE, 0.0)
    lower = np.array([-reach[0], -reach[1], receptacle.lower[2]])
    upper = np.array([reach[0], reach[1], receptacle.upper[2]])
    return Receptacle(receptacle.name, frame, lower, upper, receptacle.round_floor)


def has_walls(perception: Perception, receptacle: Receptacle) -> bool:
    """Whether ``receptacle`` holds things within walls (a bowl, a basket, a drawer, a compartment), not on a flat
    top (a plate, a saucer, a box's top, the table)."""
    if kind_of(receptacle.name) in ("drawer", "door"):
        return True
    if receptacle.name == TABLE:
        return False
    return bool(perception.box(receptacle.name).upper[2] - floor_of(receptacle) >= FLAT_RIM)


def is_closed_drawer(receptacle: Receptacle) -> bool:
    return kind_of(receptacle.name) == "drawer" and receptacle.upper[0] - receptacle.lower[0] < CLOSED_DRAWER


def is_closed(perception: Perception, receptacle: Receptacle) -> bool:
    """Whether ``receptacle`` is a drawer pushed in or a compartment whose door stands less than
    :data:`DOOR_OPEN_ENOUGH` open."""
    if kind_of(receptacle.name) != "door":
        return is_closed_drawer(receptacle)
    joints = perception.joints(receptacle.name)
    return not joints or joints[0].value < DOOR_OPEN_ENOUGH


def floor_of(receptacle: Receptacle) -> float:
    """The world height of the receptacle's floor (where what is put in it rests)."""
    return _height(receptacle, receptacle.lower[2])


def top_of(receptacle: Receptacle) -> float:
    """The world height of the top of the receptacle's free volume (a bowl's rim, a drawer's sides)."""
    return _height(receptacle, receptacle.upper[2])


def _height(receptacle: Receptacle, local_z: float) -> float:
    return float(receptacle.frame.apply(np.array([[0.0, 0.0, local_z]]))[0, 2])


def contains_xy(receptacle: Receptacle, point_xy: np.ndarray, slack: float = 0.0) -> bool:
    """Whether a point lies over the receptacle's floor (grown by ``slack`` metres each way)."""
    floor = floor_of(receptacle)
    local = receptacle.frame.inverse().apply(np.array([[point_xy[0], point_xy[1], floor]]))[0]
    lower, upper = receptacle.lower[:2] - slack, receptacle.upper[:2] + slack
    return bool(np.all(local[:2] >= lower) and np.all(local[:2] <= upper))


def object_footprint(perception: Perception, name: str) -> Footprint:
    """``name``'s footprint as perception knows it, with its outline from above."""
    center, yaw, half = perception.footprint(name)
    center, half = np.asarray(center, dtype=float), np.asarray(half, dtype=float)
    return Footprint(center, float(yaw), half, perception.outline(name))


def obstacles_for(perception: Perception, held: str, support: Receptacle) -> tuple[Footprint, ...]:
    """The footprints a thing put down on ``support`` must keep clear of: every other object's, and the
    furniture's unless the support is part of it (a drawer's floor lies within its cabinet's box)."""
    out = []
    for name in perception.objects():
        if name not in (held, support.name):
            out.append(object_footprint(perception, name))
    if support.name == TABLE:
        out += [Footprint.of_box(perception.box(n)) for n in perception.furniture() if "." not in n]
    return tuple(out)


def support_named(perception: Perception, held: str, receptacle: Receptacle) -> Support:
    """``receptacle`` as the support of a thing put down at a position in or on it (a plate's whole top)."""
    region = whole_surface(perception, receptacle) or receptacle
    return Support(region, floor_of(receptacle), obstacles_for(perception, held, receptacle))


def support_under(perception: Perception, held: str, point_xy: np.ndarray, half: np.ndarray) -> Support:
    """What a thing put down at ``point_xy`` rests on, where the program named nothing: the open container or
    drawer whose floor is under the point, else the highest flat top that bears its footprint (its middle, or
    half of it, over the top), else the table."""
    candidates: list[Receptacle] = []
    objects = perception.objects()
    for name in [*objects, *perception.furniture()]:
        if name == held or kind_of(name) in ("handle", "door"):
            continue
        seen = holds_interior(perception, name, look_again=False)
        if seen is not None and not contains_xy(seen, point_xy, INSIDE_SLACK):
            # Far from the point even as a fresh look may measure it: not worth the look (a second in full
            # perception, taken at every place on the table while the arm carries something past a cabinet).
            continue
        interior = holds_interior(perception, name)
        if interior is not None:
            # A container holds things in it, not on its rim.
            if contains_xy(interior, point_xy) and not is_closed_drawer(interior):
                return support_named(perception, held, interior)
            continue
        if name in objects or "." not in name:
            center, yaw, half_box = perception.footprint(name)
            if _bears(np.asarray(center), float(yaw), np.asarray(half_box), point_xy, half):
                top = top_face(perception, name)
                if top is not None:
                    candidates.append(top)
    if candidates:
        return support_named(perception, held, max(candidates, key=floor_of))
    return support_named(perception, held, table_top(perception))


def holds_interior(perception: Perception, name: str, look_again: bool = True) -> Receptacle | None:
    """The interior of a container or drawer (not a flat top); None where it has none. Without ``look_again``, as
    already measured (:meth:`Perception.seen_receptacle`)."""
    try:
        return perception.receptacle(name) if look_again else perception.seen_receptacle(name)
    except (UnknownObjectError, ValueError):
        return None


def _bears(center: np.ndarray, yaw: float, half_box: np.ndarray, point: np.ndarray, half: np.ndarray) -> bool:
    """Whether a footprint (``center``, turned ``yaw``, half-extents ``half_box``) is under a thing put down at
    ``point`` (half-extents ``half``): the thing's middle is over it, or half the thing is (reckoned in the
    footprint's frame). A sliver over a plate's edge is beside the plate, not on it: counting it would release the
    thing from the plate's height."""
    c, s = math.cos(yaw), math.sin(yaw)
    offset = np.asarray(point, dtype=float) - center
    local = np.array([c * offset[0] + s * offset[1], -s * offset[0] + c * offset[1]])
    if np.all(np.abs(local) <= half_box):
        return True
    overlap = np.clip(np.minimum(half_box, local + half) - np.maximum(-half_box, local - half), 0, None)
    return bool(np.prod(overlap) >= 0.5 * np.prod(2 * np.asarray(half)))


def stands_in(perception: Perception, name: str, receptacle_name: str) -> bool:
    """Whether ``name`` stands in or on ``receptacle_name``: its middle over what the receptacle holds things in or
    on (a plate's whole top; a basket's inside in its own axes, whose world-aligned box has empty corners where a
    thing beside a turned basket stands), its bottom no lower than that floor and, within walls, no higher than
    their top, else within :data:`RESTS_ON` of the surface. On the table means on it itself, not in or on
    something that stands there."""
    box = perception.box(name)
    if receptacle_name == TABLE:  # on the table itself, not in or on something standing there
        bottom = float(box.lower[2])
        others = [o for o in perception.objects() if o != name]
        return abs(bottom - floor_of(table_top(perception))) <= RESTS_ON and not any(
            _under(perception, o, box.center[:2], bottom) for o in others
        )
    region = holds(perception, receptacle_name)
    if region is None:
        return False
    if not _over(perception, region, box.center[:2]):
        return False
    floor, bottom = floor_of(region), float(box.lower[2])
    top = top_of(region) if has_walls(perception, region) else floor + RESTS_ON
    return floor - RESTS_ON <= bottom <= top


def _under(perception: Perception, name: str, point_xy: np.ndarray, bottom: float) -> bool:
    """Whether what ``name`` holds things in or on lies under ``point_xy`` no higher than ``bottom`` (so that a
    thing there with its bottom at that height stands in or on it)."""
    region = holds(perception, name)
    return region is not None and floor_of(region) <= bottom + UNDER_SLACK and _over(perception, region, point_xy)


def _over(perception: Perception, region: Receptacle, point_xy: np.ndarray) -> bool:
    """Whether a point lies over what ``region`` bears things on: a plate's whole top, else its floor."""
    return contains_xy(whole_surface(perception, region) or region, point_xy)
