"""Convex parts and the composite shapes built from them (walls of bowls, mugs, baskets, drawers).

MuJoCo collides convex geoms only, so every concave thing (a bowl, a mug, a basket) is a union of convex parts.
A part's frame is relative to its object's frame, whose origin is the centre of the object's bottom face.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal

import numpy as np

from roboscript.geometry import quat_from_axis_angle, quat_to_matrix

ShapeKind = Literal["box", "sphere", "cylinder", "capsule", "ellipsoid"]
RGBA = tuple[float, float, float, float]


@dataclass(frozen=True)
class Part:
    """One convex geom. ``size`` follows MuJoCo: half-extents for boxes, (radius, half-height) for cylinders."""

    kind: ShapeKind
    size: tuple[float, ...]
    pos: tuple[float, float, float] = (0.0, 0.0, 0.0)
    quat: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)  # (x, y, z, w)
    rgba: RGBA | None = None  # None: the object's colour

    def half_extents(self) -> np.ndarray:
        """Half-extents of the part's axis-aligned bounding box in its object's frame (conservative)."""
        if self.kind == "sphere":
            return np.full(3, self.size[0])
        if self.kind == "box" or self.kind == "ellipsoid":
            local = np.array(self.size[:3])
        elif self.kind == "cylinder":
            local = np.array([self.size[0], self.size[0], self.size[1]])
        else:  # capsule
            local = np.array([self.size[0], self.size[0], self.size[1] + self.size[0]])
        return np.abs(quat_to_matrix(np.array(self.quat))) @ local

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        half = self.half_extents()
        center = np.array(self.pos)
        return center - half, center + half


def parts_bounds(parts: tuple[Part, ...] | list[Part]) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned bounds of a set of parts in their object's frame."""
    lowers, uppers = zip(*(p.bounds() for p in parts), strict=True)
    return np.min(lowers, axis=0), np.max(uppers, axis=0)


def _quat_multiply(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array(
        [
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz,
        ]
    )


def ring_wall(
    bottom_radius: float,
    top_radius: float,
    height: float,
    thickness: float,
    segments: int,
    z0: float = 0.0,
    rgba: RGBA | None = None,
) -> list[Part]:
    """A (possibly flared) circular wall from box segments, its bottom edge at height ``z0``.

    Segments overlap slightly so that no gap opens between them, even for small objects.
    """
    flare = math.atan2(top_radius - bottom_radius, height)
    slant = math.hypot(height, top_radius - bottom_radius)
    mid_radius = (bottom_radius + top_radius) / 2 + thickness / 2 * math.cos(flare)
    tangential = 2 * math.pi * (max(bottom_radius, top_radius) + thickness) / segments * 0.56
    parts = []
    for k in range(segments):
        theta = 2 * math.pi * k / segments
        tilt = quat_from_axis_angle(np.array([0.0, 1.0, 0.0]), flare)
        yaw = quat_from_axis_angle(np.array([0.0, 0.0, 1.0]), theta)
        q = _quat_multiply(yaw, tilt)
        parts.append(
            Part(
                "box",
                (thickness / 2, tangential, slant / 2),
                (mid_radius * math.cos(theta), mid_radius * math.sin(theta), z0 + height / 2),
                tuple(q),
                rgba,
            )
        )
    return parts


def disk(radius: float, thickness: float, z0: float = 0.0, rgba: RGBA | None = None) -> Part:
    """A flat cylinder whose bottom face is at ``z0``."""
    return Part("cylinder", (radius, thickness / 2), (0.0, 0.0, z0 + thickness / 2), rgba=rgba)


def open_box(
    length: float,
    width: float,
    height: float,
    thickness: float,
    z0: float = 0.0,
    rgba: RGBA | None = None,
) -> list[Part]:
    """A rectangular tray open at the top: floor and four walls, outer size ``length x width x height``."""
    lx, wy, t = length / 2, width / 2, thickness / 2
    wall_h = (height - thickness) / 2
    wall_z = z0 + thickness + wall_h
    return [
        Part("box", (lx, wy, t), (0.0, 0.0, z0 + t), rgba=rgba),
        Part("box", (t, wy, wall_h), (lx - t, 0.0, wall_z), rgba=rgba),
        Part("box", (t, wy, wall_h), (-lx + t, 0.0, wall_z), rgba=rgba),
        Part("box", (lx, t, wall_h), (0.0, wy - t, wall_z), rgba=rgba),
        Part("box", (lx, t, wall_h), (0.0, -wy + t, wall_z), rgba=rgba),
    ]


def arc_of_capsules(
    radius: float,
    thickness: float,
    start: float,
    stop: float,
    segments: int,
    center: tuple[float, float, float],
    plane: Literal["xz", "xy"] = "xz",
    rgba: RGBA | None = None,
) -> list[Part]:
    """Capsules along a circular arc (mug handles, bananas), angles in radians from the arc plane's first axis."""
    parts = []
    step = (stop - start) / segments
    chord = 2 * radius * math.sin(abs(step) / 2)
    for k in range(segments):
        a = start + (k + 0.5) * step
        u = np.array([math.cos(a), 0.0, math.sin(a)]) if plane == "xz" else np.array([math.cos(a), math.sin(a), 0])
        tangent = (
            np.array([-math.sin(a), 0.0, math.cos(a)]) if plane == "xz" else np.array([-math.sin(a), math.cos(a), 0.0])
        )
        pos = np.array(center) + radius * math.cos(step / 2) * u
        # Rotate the capsule's z axis onto the tangent.
        axis = np.cross([0.0, 0.0, 1.0], tangent)
        angle = math.acos(float(np.clip(tangent[2], -1.0, 1.0)))
        q = quat_from_axis_angle(axis, angle) if np.linalg.norm(axis) > 1e-9 else np.array([0.0, 0, 0, 1])
        parts.append(Part("capsule", (thickness, chord / 2), tuple(pos), tuple(q), rgba))
    return parts
