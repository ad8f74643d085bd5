"""Footprints: the turned rectangle of least area around what an object covers of the table, seen from above, and
the convex outline within it."""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import ConvexHull, QhullError


def footprint_of(points: np.ndarray, trim: float = 0.5) -> tuple[np.ndarray, float, np.ndarray]:
    """``(center_xy, yaw, half_extents_xy)`` of the points seen from above: the turned rectangle of least area
    around them (``trim`` percent of stray points cut on each side), its longer side along ``yaw`` in
    [-pi/2, pi/2).

    Principal axes would be cheaper but are pulled off the sides by how unevenly the views sample a surface: on
    a box a few degrees of error add millimetres to its width, which decide whether a gripper fits round it."""
    xy = points[:, :2] - points[:, :2].mean(axis=0)
    coarse = np.radians(np.arange(0.0, 90.0, 2.0))
    best = min(coarse, key=lambda a: _rectangle(xy, a, trim)[0])
    fine = best + np.radians(np.arange(-2.0, 2.01, 0.25))
    angle = min(fine, key=lambda a: _rectangle(xy, a, trim)[0])
    _, lower, upper = _rectangle(xy, angle, trim)
    half = (upper - lower) / 2
    yaw = float(angle)
    if half[1] > half[0]:  # the longer side along the yaw
        half = half[::-1]
        yaw += math.pi / 2
    yaw = (yaw + math.pi / 2) % math.pi - math.pi / 2
    axes = np.array([[math.cos(angle), math.sin(angle)], [-math.sin(angle), math.cos(angle)]])
    center = points[:, :2].mean(axis=0) + ((lower + upper) / 2) @ axes
    return center, yaw, half


def _rectangle(xy: np.ndarray, angle: float, trim: float) -> tuple[float, np.ndarray, np.ndarray]:
    """Area and local corners of the trimmed rectangle around ``xy`` along ``angle``."""
    c, s = math.cos(angle), math.sin(angle)
    local = xy @ np.array([[c, -s], [s, c]])
    lower, upper = np.percentile(local, trim, axis=0), np.percentile(local, 100 - trim, axis=0)
    return float(np.prod(upper - lower)), lower, upper


def outline_of(
    points: np.ndarray, trim: float = 0.5, footprint: tuple[np.ndarray, float, np.ndarray] | None = None
) -> np.ndarray:
    """The convex outline, seen from above, of the points within their footprint (:func:`footprint_of`, the
    stray points it trims left out; ``footprint``: that of the points, where it is known already): its corners
    ``(K, 2)`` counter-clockwise round it; the footprint's corners where the points span no area."""
    center, yaw, half = footprint_of(points, trim) if footprint is None else footprint
    axes = np.array([[math.cos(yaw), math.sin(yaw)], [-math.sin(yaw), math.cos(yaw)]])
    xy = np.asarray(points, dtype=float)[:, :2]
    within = xy[np.all(np.abs((xy - center) @ axes.T) <= half + 1e-3, axis=1)]
    try:
        hull = ConvexHull(within)
    except (QhullError, ValueError):  # fewer than three points, or all on a line
        return rectangle_outline(center, yaw, half)
    return within[hull.vertices]


def rectangle_outline(center: np.ndarray, yaw: float, half: np.ndarray) -> np.ndarray:
    """The corners ``(4, 2)`` of the rectangle ``(center, yaw, half)``, counter-clockwise."""
    axes = np.array([[math.cos(yaw), math.sin(yaw)], [-math.sin(yaw), math.cos(yaw)]])
    signs = np.array([[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]])
    return np.asarray(center, dtype=float) + (signs * np.asarray(half, dtype=float)) @ axes
