"""Furniture: the table and articulated cabinets with drawers and hinged doors.

A cabinet's local frame has its origin at the centre of its footprint on the surface it stands on, +x pointing
out of its front. Rows are listed from the top down; drawers, doors and handles are numbered from the top down,
as the tool API names them: ``cabinet.drawer_0`` is the top drawer, ``cabinet.handle_k`` belongs to the k-th row
from the top, whether that row is a drawer or a door.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal

import mujoco
import numpy as np

from roboscript.geometry import quat_from_yaw, quat_to_mujoco

RowKind = Literal["drawer", "door"]
HingeSide = Literal["left", "right"]

CABINET_RGBA = (0.86, 0.84, 0.8, 1.0)
FRONT_RGBA = (0.93, 0.92, 0.88, 1.0)
HANDLE_RGBA = (0.25, 0.25, 0.27, 1.0)
TABLE_RGBA = (0.62, 0.48, 0.33, 1.0)


@dataclass(frozen=True)
class TableSpec:
    """A table centred at the world origin; ``height`` is the height of its top surface."""

    length: float = 1.3  # along x
    width: float = 1.8  # along y
    height: float = 0.82
    thickness: float = 0.04


@dataclass(frozen=True)
class CabinetRow:
    kind: RowKind
    height: float = 0.14
    open: float = 0.0  # how far it starts open: metres for a drawer, radians for a door
    # A door's hinge, on the left or right edge of the opening as seen from in front of the cabinet (left: its
    # local -y).
    hinge: HingeSide = "left"


@dataclass(frozen=True)
class CabinetSpec:
    """A chest of drawers (and door compartments) standing on the table."""

    name: str
    position: tuple[float, float]
    yaw: float = 0.0  # radians; 0: the front faces +x
    rows: tuple[CabinetRow, ...] = field(
        default_factory=lambda: (CabinetRow("drawer"), CabinetRow("drawer"), CabinetRow("drawer"))
    )
    width: float = 0.44
    depth: float = 0.36
    panel: float = 0.015
    plinth: float = 0.02

    @property
    def height(self) -> float:
        return self.plinth + sum(r.height for r in self.rows) + self.panel * (len(self.rows) + 1)

    def footprint(self) -> tuple[np.ndarray, np.ndarray, float]:
        """Centre (x, y), half-extents (along local x, y) and yaw of the footprint, handles included."""
        return np.array(self.position), np.array([self.depth / 2 + 0.05, self.width / 2]), self.yaw

    def row_parts(self) -> list[tuple[CabinetRow, str]]:
        """Each row with the name of its drawer or door, from the top down."""
        names = self.part_names()
        return [(row, names[2 * k]) for k, row in enumerate(self.rows)]

    def row_middles(self) -> list[float]:
        """The height of each row's middle above the cabinet's base, from the top down."""
        middles, z = [], self.height
        for row in self.rows:
            z -= self.panel
            middles.append(z - row.height / 2)
            z -= row.height
        return middles

    def part_names(self) -> list[str]:
        names = []
        drawers = doors = 0
        for k, row in enumerate(self.rows):
            if row.kind == "drawer":
                names.append(f"{self.name}.drawer_{drawers}")
                drawers += 1
            else:
                names.append(f"{self.name}.door_{doors}")
                doors += 1
            names.append(f"{self.name}.handle_{k}")
        return names


def _add_box(body: mujoco.MjsBody, name: str, half: tuple[float, float, float], pos, rgba, **kwargs) -> None:
    body.add_geom(name=name, type=mujoco.mjtGeom.mjGEOM_BOX, size=list(half), pos=list(pos), rgba=list(rgba), **kwargs)


def add_table(spec: mujoco.MjSpec, table: TableSpec) -> None:
    """A static table: top and four legs, named ``table``."""
    body = spec.worldbody.add_body(name="table")
    top_z = table.height - table.thickness / 2
    _add_box(body, "table/top", (table.length / 2, table.width / 2, table.thickness / 2), (0, 0, top_z), TABLE_RGBA)
    leg_h = (table.height - table.thickness) / 2
    for i, (sx, sy) in enumerate(((1, 1), (1, -1), (-1, 1), (-1, -1))):
        pos = (sx * (table.length / 2 - 0.05), sy * (table.width / 2 - 0.05), leg_h)
        _add_box(body, f"table/leg_{i}", (0.03, 0.03, leg_h), pos, TABLE_RGBA)


def _add_handle(parent: mujoco.MjsBody, name: str, pos: np.ndarray, vertical: bool) -> None:
    """A bar handle on two standoffs, 4 cm proud of the front: room for fingers behind it."""
    handle = parent.add_body(name=name, pos=list(pos))
    length = 0.12 if not vertical else 0.10
    bar_quat = [1, 0, 0, 0] if vertical else [math.cos(math.pi / 4), math.sin(math.pi / 4), 0, 0]
    handle.add_geom(
        name=f"{name}/bar",
        type=mujoco.mjtGeom.mjGEOM_CAPSULE,
        size=[0.008, length / 2, 0],
        pos=[0.032, 0, 0],
        quat=bar_quat,
        rgba=list(HANDLE_RGBA),
        friction=[1.2, 0.005, 0.0001],
    )
    offset = np.array([0, 0, length / 2 - 0.01]) if vertical else np.array([0, length / 2 - 0.01, 0])
    for i, sign in enumerate((1, -1)):
        _add_box(handle, f"{name}/standoff_{i}", (0.014, 0.006, 0.006), (0.014, 0, 0) + sign * offset, HANDLE_RGBA)


def add_cabinet(spec: mujoco.MjSpec, cabinet: CabinetSpec, base_height: float) -> list[tuple[str, str]]:
    """Adds the cabinet standing at ``base_height``; returns ``(body_a, body_b)`` pairs to exclude from contact.

    Drawers slide on prismatic joints along local +x; doors swing on vertical hinges so that a positive joint
    angle opens them outward. Joint names are the part names with ``.joint`` appended.
    """
    w, d, t = cabinet.width, cabinet.depth, cabinet.panel
    quat = quat_to_mujoco(quat_from_yaw(cabinet.yaw))
    carcass = spec.worldbody.add_body(
        name=cabinet.name, pos=[cabinet.position[0], cabinet.position[1], base_height], quat=list(quat)
    )
    height = cabinet.height
    # Carcass: plinth, sides, back, top; dividers are added row by row below.
    _add_box(
        carcass,
        f"{cabinet.name}/plinth",
        (d / 2, w / 2, cabinet.plinth / 2),
        (0, 0, cabinet.plinth / 2),
        CABINET_RGBA,
    )
    for side, sy in (("left", 1), ("right", -1)):
        _add_box(
            carcass,
            f"{cabinet.name}/side_{side}",
            (d / 2, t / 2, height / 2),
            (0, sy * (w / 2 - t / 2), height / 2),
            CABINET_RGBA,
        )
    _add_box(
        carcass,
        f"{cabinet.name}/back",
        (t / 2, w / 2, height / 2),
        (-d / 2 + t / 2, 0, height / 2),
        CABINET_RGBA,
    )

    excludes: list[tuple[str, str]] = []
    inner_w = w - 2 * t
    z = height
    drawers = doors = 0
    for k, row in enumerate(cabinet.rows):
        # The panel above this row (the top, or the divider shared with the row above).
        _add_box(carcass, f"{cabinet.name}/panel_{k}", (d / 2, w / 2, t / 2), (0, 0, z - t / 2), CABINET_RGBA)
        z_top = z - t
        z_bottom = z_top - row.height
        z_mid = (z_top + z_bottom) / 2
        gap = 0.003
        if row.kind == "drawer":
            name = f"{cabinet.name}.drawer_{drawers}"
            drawers += 1
            body = carcass.add_body(name=name, pos=[d / 2, 0, z_mid])
            body.add_joint(
                name=f"{name}.joint",
                type=mujoco.mjtJoint.mjJNT_SLIDE,
                axis=[1, 0, 0],
                range=[0, 0.75 * d],
                damping=8.0,
                frictionloss=1.0,
                armature=0.05,
            )
            front_h = row.height - 2 * gap
            _add_box(body, f"{name}/front", (t / 2, inner_w / 2 - gap, front_h / 2), (-t / 2, 0, 0), FRONT_RGBA)
            tray_depth = d - 2 * t - 0.01
            tray_h = row.height * 0.75
            tray_w = inner_w - 2 * gap
            bottom_z = -row.height / 2 + gap
            tray_cx = -t - tray_depth / 2
            wall = 0.008
            _add_box(
                body,
                f"{name}/bottom",
                (tray_depth / 2, tray_w / 2, wall / 2),
                (tray_cx, 0, bottom_z + wall / 2),
                CABINET_RGBA,
            )
            for side, sy in (("left", 1), ("right", -1)):
                _add_box(
                    body,
                    f"{name}/side_{side}",
                    (tray_depth / 2, wall / 2, tray_h / 2),
                    (tray_cx, sy * (tray_w / 2 - wall / 2), bottom_z + tray_h / 2),
                    CABINET_RGBA,
                )
            _add_box(
                body,
                f"{name}/back",
                (wall / 2, tray_w / 2, tray_h / 2),
                (-t - tray_depth + wall / 2, 0, bottom_z + tray_h / 2),
                CABINET_RGBA,
            )
            _add_handle(body, f"{cabinet.name}.handle_{k}", np.array([0.0, 0.0, 0.0]), vertical=False)
        else:
            name = f"{cabinet.name}.door_{doors}"
            doors += 1
            # Hinged on the left (-y) or right (+y) edge of the opening, the axis pointing so that positive angles
            # swing the door outward.
            side = -1.0 if row.hinge == "left" else 1.0
            body = carcass.add_body(name=name, pos=[d / 2, side * inner_w / 2, z_mid])
            body.add_joint(
                name=f"{name}.joint",
                type=mujoco.mjtJoint.mjJNT_HINGE,
                axis=[0, 0, side],
                range=[0, math.radians(100)],
                damping=2.0,
                frictionloss=0.3,
                armature=0.05,
            )
            door_w = inner_w - 2 * gap
            _add_box(
                body,
                f"{name}/panel",
                (t / 2, door_w / 2, (row.height - 2 * gap) / 2),
                (-t / 2, -side * (gap + door_w / 2), 0),
                FRONT_RGBA,
            )
            handle_at = np.array([0.0, -side * (door_w - 0.05), 0.0])
            _add_handle(body, f"{cabinet.name}.handle_{k}", handle_at, vertical=True)
            # A shelf inside the compartment so that things put behind the door rest on something.
            _add_box(
                carcass,
                f"{name}/shelf",
                (d / 2 - t, inner_w / 2, 0.004),
                (0, 0, z_bottom + 0.004),
                CABINET_RGBA,
            )
        excludes.append((cabinet.name, name))
        z = z_bottom
    _add_box(
        carcass,
        f"{cabinet.name}/panel_{len(cabinet.rows)}",
        (d / 2, w / 2, t / 2),
        (0, 0, z - t / 2),
        CABINET_RGBA,
    )
    # Moving parts are guided by their joints; contacts between them and the carcass would only add chatter.
    moving = [b for _, b in excludes]
    for i, a in enumerate(moving):
        for b in moving[i + 1 :]:
            excludes.append((a, b))
    return excludes


def drawer_interior(model: mujoco.MjModel, drawer_body: str) -> tuple[np.ndarray, np.ndarray]:
    """The drawer's inner volume in its body frame, as (lower, upper), from its tray geoms."""
    bottom = model.geom(f"{drawer_body}/bottom")
    side = model.geom(f"{drawer_body}/side_left")
    back = model.geom(f"{drawer_body}/back")
    x_hi = bottom.pos[0] + bottom.size[0]
    x_lo = back.pos[0] + back.size[0]
    y_half = side.pos[1] - side.size[1]
    z_lo = bottom.pos[2] + bottom.size[2]
    z_hi = side.pos[2] + side.size[2]
    return np.array([x_lo, -y_half, z_lo]), np.array([x_hi, y_half, z_hi])


def compartment_interior(model: mujoco.MjModel, door_body: str) -> tuple[np.ndarray, np.ndarray]:
    """The free inside of the compartment behind a door, as (lower, upper) in its cabinet's frame: from the shelf
    it has for a floor to the panel above, between the cabinet's sides, and from its back to behind the door."""
    door = model.body(door_body)
    cabinet = door_body.split(".", 1)[0]
    shelf = model.geom(f"{door_body}/shelf")
    panel = model.geom(f"{door_body}/panel")
    side = model.geom(f"{cabinet}/side_left")
    back = model.geom(f"{cabinet}/back")
    ceiling = door.pos[2] + panel.size[2] + 0.003  # the panel fills its opening but for a 3 mm gap
    y_half = side.pos[1] - side.size[1]
    x_lo = back.pos[0] + back.size[0]
    x_hi = door.pos[0] - 2 * panel.size[0]
    return np.array([x_lo, -y_half, shelf.pos[2] + shelf.size[2]]), np.array([x_hi, y_half, ceiling])
