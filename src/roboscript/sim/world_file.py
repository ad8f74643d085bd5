"""World files: a YAML (or JSON) description of a scene, parsed and validated into a :class:`WorldSpec`.

A world file names the robot, the table, furniture, objects with their poses, and optionally the camera rig and
how much to randomise object poses. Every problem is reported as a :class:`WorldFileError` that names the file,
the entry (``objects[3] 'apple'``) and what is wrong, with the valid choices where there are any.

Example::

    name: world_2_pick_and_place
    robot: panda
    furniture:
      - {name: cabinet, type: cabinet, position: [-0.42, 0.62], rows: [drawer, drawer, drawer]}
    objects:
      - {name: apple, type: apple, position: [0.0, -0.2]}
      - {name: lemon, type: lemon, on: white_plate, position: [0.02, 0.0]}
      - {name: gelatin_box, type: gelatin_box, inside: cabinet.drawer_1}
    randomize: {position: 0.02, yaw: 30}
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from roboscript.datafile import DataFileError, Reader, entry_label, read_data_file
from roboscript.errors import unknown_name
from roboscript.names import TABLE, kind_of
from roboscript.objects import ObjectType, object_types
from roboscript.objects.library import OBJECT_LISTING
from roboscript.robots import ROBOTS
from roboscript.sim.cameras import CameraSpec, default_camera_rig
from roboscript.sim.furniture import CabinetRow, CabinetSpec, TableSpec

TABLE_NAME = TABLE
ROBOT_BASE_XY = (-0.45, 0.0)
ROBOT_BASE_RADIUS = 0.12
OVERLAP_MARGIN = 0.004
VALID_ROBOTS = tuple(ROBOTS)


class WorldFileError(DataFileError):
    """A world file that cannot be loaded; the message names the file, the entry and the problem."""

    kind = "world"


@dataclass(frozen=True)
class ObjectPlacement:
    """One object instance. ``support`` is ``table``, another object's name (``on``), or a drawer (``inside``)."""

    name: str
    type: ObjectType
    position: tuple[float, ...]  # (x, y) on the table; an (x, y) offset in the support's frame otherwise
    yaw: float = 0.0  # radians
    support: str = "table"
    support_kind: str = "table"  # "table", "on" or "inside"


@dataclass(frozen=True)
class Randomization:
    position: float = 0.0  # metres, uniform in [-p, p] on x and y
    yaw: float = 0.0  # radians, uniform in [-a, a]


@dataclass(frozen=True)
class WorldSpec:
    """A validated world: everything needed to build the simulation."""

    name: str
    source: str
    description: str = ""
    robot: str = "panda"
    table: TableSpec = field(default_factory=TableSpec)
    cabinets: tuple[CabinetSpec, ...] = ()
    objects: tuple[ObjectPlacement, ...] = ()
    cameras: tuple[CameraSpec, ...] = field(default_factory=default_camera_rig)
    randomization: Randomization = field(default_factory=Randomization)

    def object_names(self) -> list[str]:
        return [o.name for o in self.objects]

    def part_names(self) -> list[str]:
        return [p for c in self.cabinets for p in c.part_names()]

    def query_names(self) -> list[str]:
        """Every name a program may use here, in the order of the original benchmark's queries: the table, the
        furniture, the objects, then each piece of furniture's drawers and doors before its handles."""
        parts = sorted(self.part_names(), key=lambda p: (p.split(".")[0], kind_of(p) == "handle"))
        return [TABLE_NAME, *(c.name for c in self.cabinets), *self.object_names(), *parts]

    def randomized(self, seed: int) -> WorldSpec:
        """A copy with table objects' poses jittered by :attr:`randomization`, deterministic for ``seed``.

        Draws again (up to 100 times) until nothing overlaps; raises :class:`WorldFileError` if it never fits.
        """
        r = self.randomization
        if r.position == 0 and r.yaw == 0:
            return self
        rng = np.random.default_rng(seed)
        for _ in range(100):
            objects = []
            for o in self.objects:
                dx, dy = rng.uniform(-r.position, r.position, size=2)
                dyaw = rng.uniform(-r.yaw, r.yaw)
                if o.support_kind == "table":
                    objects.append(replace(o, position=(o.position[0] + dx, o.position[1] + dy), yaw=o.yaw + dyaw))
                else:
                    objects.append(replace(o, yaw=o.yaw + dyaw))
            candidate = replace(self, objects=tuple(objects))
            try:
                _check_layout(candidate)
            except WorldFileError:
                continue
            return candidate
        raise WorldFileError(
            self.source,
            "randomize",
            f"no overlap-free layout found in 100 draws with seed {seed}; reduce randomize.position or randomize.yaw",
        )


# ---------------------------------------------------------------------------------------------------------------
# Parsing


def _reader(source: str, entry: str, data: Any, allowed: set[str]) -> Reader:
    return Reader(source, entry, data, allowed, WorldFileError)


_WORLD_FIELDS = {"name", "description", "robot", "table", "furniture", "objects", "cameras", "randomize"}
_OBJECT_FIELDS = {"name", "type", "position", "yaw", "on", "inside"}
DRAWER_OPENS_AT_MOST = 0.25  # metres a world file may start a drawer pulled out (its travel is 75% of the depth)
DOOR_OPENS_AT_MOST = 90.0  # degrees a world file may start a door open
_CABINET_FIELDS = {"name", "type", "position", "yaw", "rows", "width", "depth"}
_CAMERA_FIELDS = {"name", "position", "look_at", "fovy", "width", "height"}


def _parse_rows(reader: Reader, rows: Any) -> tuple[CabinetRow, ...]:
    if not isinstance(rows, list) or not rows:
        reader.fail(f"field 'rows' must be a non-empty list of 'drawer' or 'door' entries, got {rows!r}")
    out = []
    for i, row in enumerate(rows):
        if isinstance(row, str):
            row = {"kind": row}
        r = _reader(reader.source, f"{reader.entry}.rows[{i}]", row, {"kind", "height", "open", "hinge"})
        kind = r.string("kind")
        if kind not in ("drawer", "door"):
            r.fail(f"row kind must be 'drawer' or 'door', got {kind!r}")
        height = r.number("height", 0.14)
        if not 0.06 <= height <= 0.4:
            r.fail(f"row height must be between 0.06 and 0.4 m, got {height}")
        opened = r.number("open", 0.0)
        most = DRAWER_OPENS_AT_MOST if kind == "drawer" else DOOR_OPENS_AT_MOST
        if not 0.0 <= opened <= most:
            unit = "m (a drawer's pull)" if kind == "drawer" else "degrees (a door's swing)"
            r.fail(f"row open must be between 0 and {most:g} {unit}, got {opened}")
        hinge = r.string("hinge", "left")
        if hinge not in ("left", "right") or (kind == "drawer" and "hinge" in r.data):
            r.fail(
                f"field 'hinge' is a door's: 'left' or 'right' as seen from in front of the cabinet (drawers have "
                f"none), got {hinge!r} on a {kind}"
            )
        out.append(CabinetRow(kind, height, opened if kind == "drawer" else math.radians(opened), hinge))
    return tuple(out)


def _parse_furniture(source: str, items: Any) -> tuple[CabinetSpec, ...]:
    if items is None:
        return ()
    if not isinstance(items, list):
        raise WorldFileError(source, "furniture", f"must be a list, got {type(items).__name__}")
    cabinets = []
    for i, item in enumerate(items):
        r = _reader(source, entry_label("furniture", i, item), item, _CABINET_FIELDS)
        kind = r.string("type")
        if kind != "cabinet":
            r.fail(f"unknown furniture type {kind!r}; valid types: cabinet")
        name = r.string("name")
        if "." in name or "/" in name:
            r.fail(f"name {name!r} must not contain '.' or '/' (they separate part names)")
        cabinets.append(
            CabinetSpec(
                name=name,
                position=r.vector("position", (2,)),
                yaw=math.radians(r.number("yaw", 0.0)),
                rows=_parse_rows(r, r.data.get("rows", ["drawer", "drawer", "drawer"])),
                width=r.number("width", 0.44),
                depth=r.number("depth", 0.36),
            )
        )
    return tuple(cabinets)


def _parse_objects(source: str, items: Any, part_names: set[str]) -> tuple[ObjectPlacement, ...]:
    if not isinstance(items, list):
        raise WorldFileError(source, "objects", f"must be a list of objects, got {type(items).__name__}")
    library = object_types()
    placements: list[ObjectPlacement] = []
    seen: set[str] = set()
    for i, item in enumerate(items):
        r = _reader(source, entry_label("objects", i, item), item, _OBJECT_FIELDS)
        name = r.string("name")
        if name in seen or name in part_names or name == TABLE_NAME:
            r.fail(f"name {name!r} is already used; object names must be unique")
        if "." in name or "/" in name:
            r.fail(f"name {name!r} must not contain '.' or '/'")
        type_name = r.string("type")
        if type_name not in library:
            r.fail(unknown_name("object type", type_name, library, OBJECT_LISTING))
        if "on" in r.data and "inside" in r.data:
            r.fail("give either 'on' or 'inside', not both")
        support, kind = "table", "table"
        if "on" in r.data:
            support, kind = r.string("on"), "on"
            if support not in seen:
                r.fail(
                    f"'on: {support}' must name an object listed before this one; listed so far: "
                    f"{', '.join(sorted(seen)) or 'none'}"
                )
        elif "inside" in r.data:
            support, kind = r.string("inside"), "inside"
            drawers = sorted(p for p in part_names if kind_of(p) == "drawer")
            if support not in drawers:
                r.fail(f"'inside: {support}' must name a drawer; drawers in this world: {', '.join(drawers) or 'none'}")
        default_pos = None if kind == "table" else (0.0, 0.0)
        position = r.vector("position", (2,), default_pos)
        placements.append(
            ObjectPlacement(name, library[type_name], position, math.radians(r.number("yaw", 0.0)), support, kind)
        )
        seen.add(name)
    return tuple(placements)


def _parse_cameras(source: str, items: Any) -> tuple[CameraSpec, ...]:
    if items is None or items == "default":
        return default_camera_rig()
    if not isinstance(items, list) or not items:
        raise WorldFileError(source, "cameras", "must be 'default' or a non-empty list of cameras")
    cameras = []
    for i, item in enumerate(items):
        r = _reader(source, f"cameras[{i}]", item, _CAMERA_FIELDS)
        cam = CameraSpec(
            name=r.string("name"),
            position=r.vector("position", (3,)),
            look_at=r.vector("look_at", (3,)),
            fovy=r.number("fovy", 45.0),
            width=int(r.number("width", 640)),
            height=int(r.number("height", 480)),
        )
        if np.linalg.norm(np.subtract(cam.look_at, cam.position)) < 1e-6:
            r.fail("position and look_at must differ")
        if not 1 <= cam.fovy < 180:
            r.fail(f"fovy must be in [1, 180) degrees, got {cam.fovy}")
        if not (16 <= cam.width <= 4096 and 16 <= cam.height <= 4096):
            r.fail(f"width and height must be within 16..4096 pixels, got {cam.width}x{cam.height}")
        cameras.append(cam)
    names = [c.name for c in cameras]
    if len(set(names)) != len(names):
        raise WorldFileError(source, "cameras", f"camera names must be unique, got {names}")
    return tuple(cameras)


def parse_world(data: Any, source: str = "<memory>") -> WorldSpec:
    """Validates a world given as parsed YAML/JSON data; raises :class:`WorldFileError`."""
    r = _reader(source, "world", data, _WORLD_FIELDS)
    robot = r.string("robot", "panda")
    if robot not in VALID_ROBOTS:
        r.fail(f"unknown robot {robot!r}; valid robots: {', '.join(VALID_ROBOTS)}")
    table = TableSpec()
    if "table" in r.data:
        t = _reader(source, "table", r.data["table"], {"size", "height"})
        size = t.vector("size", (2,), (table.length, table.width))
        table = TableSpec(length=size[0], width=size[1], height=t.number("height", table.height))
        if min(size) < 0.5 or not 0.4 <= table.height <= 1.2:
            t.fail("table size must be at least 0.5 m and height within 0.4..1.2 m")
    cabinets = _parse_furniture(source, r.data.get("furniture"))
    part_names = {p for c in cabinets for p in c.part_names()}
    if len({c.name for c in cabinets}) != len(cabinets):
        raise WorldFileError(source, "furniture", "furniture names must be unique")
    randomization = Randomization()
    if "randomize" in r.data:
        rr = _reader(source, "randomize", r.data["randomize"], {"position", "yaw"})
        randomization = Randomization(rr.number("position", 0.0), math.radians(rr.number("yaw", 0.0)))
        if not 0 <= randomization.position <= 0.2:
            rr.fail(f"position must be within 0..0.2 m, got {randomization.position}")
    world = WorldSpec(
        name=r.string("name"),
        source=source,
        description=str(r.data.get("description", "")),
        robot=robot,
        table=table,
        cabinets=cabinets,
        objects=_parse_objects(source, r.required("objects"), part_names),
        cameras=_parse_cameras(source, r.data.get("cameras")),
        randomization=randomization,
    )
    _check_layout(world)
    return world


def load_world_file(path: str | Path) -> WorldSpec:
    """Reads and validates a ``.yaml``/``.yml``/``.json`` world file."""
    return parse_world(read_data_file(path, WorldFileError), str(path))


# ---------------------------------------------------------------------------------------------------------------
# Layout checks: footprints as oriented rectangles in the plane of their support.


@dataclass(frozen=True)
class _Footprint:
    label: str
    center: np.ndarray
    half: np.ndarray
    yaw: float

    def axes(self) -> np.ndarray:
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return np.array([[c, s], [-s, c]])

    def corners(self) -> np.ndarray:
        ax = self.axes()
        signs = np.array([[1, 1], [1, -1], [-1, 1], [-1, -1]])
        return self.center + (signs * self.half) @ ax


def _overlap(a: _Footprint, b: _Footprint, margin: float) -> bool:
    """Separating-axis test for two oriented rectangles, grown by ``margin``."""
    for axis in np.vstack([a.axes(), b.axes()]):
        pa, pb = a.corners() @ axis, b.corners() @ axis
        if pa.max() + margin <= pb.min() or pb.max() + margin <= pa.min():
            return False
    return True


def _object_footprint(o: ObjectPlacement, center: np.ndarray) -> _Footprint:
    lower, upper = o.type.bounds
    local_center = (lower[:2] + upper[:2]) / 2
    c, s = math.cos(o.yaw), math.sin(o.yaw)
    world_offset = np.array([c * local_center[0] - s * local_center[1], s * local_center[0] + c * local_center[1]])
    return _Footprint(f"objects {o.name!r}", center + world_offset, (upper[:2] - lower[:2]) / 2, o.yaw)


def placements_overlap(a: ObjectPlacement, b: ObjectPlacement, margin: float) -> bool:
    """Whether two objects on the table come closer than ``margin`` (their footprints as turned rectangles)."""
    return _overlap(
        _object_footprint(a, np.array(a.position[:2])), _object_footprint(b, np.array(b.position[:2])), margin
    )


def _entry(world: WorldSpec, name: str) -> str:
    index = world.object_names().index(name)
    return f"objects[{index}] {name!r}"


def _check_layout(world: WorldSpec) -> None:
    """Raises :class:`WorldFileError` for objects that overlap, leave the table or block the robot."""
    table = world.table
    furniture = [_Footprint(f"furniture {c.name!r}", *c.footprint()) for c in world.cabinets]
    robot = _Footprint("the robot base", np.array(ROBOT_BASE_XY), np.full(2, ROBOT_BASE_RADIUS), 0.0)
    for i, c in enumerate(furniture):
        corners = c.corners()
        if np.any(np.abs(corners[:, 0]) > table.length / 2 + 0.02) or np.any(
            np.abs(corners[:, 1]) > table.width / 2 + 0.02
        ):
            raise WorldFileError(
                world.source, f"furniture[{i}] {world.cabinets[i].name!r}", "does not fit on the table"
            )
        for other in [robot, *furniture[:i]]:
            if _overlap(c, other, OVERLAP_MARGIN):
                raise WorldFileError(
                    world.source, f"furniture[{i}] {world.cabinets[i].name!r}", f"overlaps {other.label}"
                )
    by_support: dict[str, list[tuple[ObjectPlacement, _Footprint]]] = {}
    for o in world.objects:
        fp = _object_footprint(o, np.array(o.position[:2]))
        if o.support_kind == "table":
            corners = fp.corners()
            if np.any(np.abs(corners[:, 0]) > table.length / 2) or np.any(np.abs(corners[:, 1]) > table.width / 2):
                raise WorldFileError(
                    world.source,
                    _entry(world, o.name),
                    f"position {list(o.position)} puts it off the table "
                    f"(x within +-{table.length / 2}, y within +-{table.width / 2})",
                )
            for other in [robot, *furniture]:
                if _overlap(fp, other, OVERLAP_MARGIN):
                    raise WorldFileError(
                        world.source, _entry(world, o.name), f"at {list(o.position)} overlaps {other.label}"
                    )
        for other_o, other_fp in by_support.get(o.support, []):
            if _overlap(fp, other_fp, OVERLAP_MARGIN):
                raise WorldFileError(
                    world.source,
                    _entry(world, o.name),
                    f"at {list(o.position)} overlaps objects {other_o.name!r} at "
                    f"{list(other_o.position)} (both on {o.support})",
                )
        by_support.setdefault(o.support, []).append((o, fp))
