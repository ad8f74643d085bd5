"""The direction a seen face looks at a point of it: ``get_plane_normal``'s answer from points, not from geoms."""

from __future__ import annotations

import math

import numpy as np

from roboscript.perception.reconstruction.instances import fit_box

PLANE_RADIUS = 0.03  # metres around the queried point whose points a face's plane is fitted to
LEAST_POINTS = 10  # points near the queried point below which the nearest face of the box answers
AGREEING = math.cos(math.radians(30))  # normals within this of the prevailing one are of its face


def plane_normal_at(
    points: np.ndarray, position: np.ndarray, radius: float = PLANE_RADIUS, normals: np.ndarray | None = None
) -> np.ndarray:
    """The outward normal of the face at ``position``, from the points within ``radius`` of it.

    Given the points' ``normals``, the way most of them point there: a plane fitted to the points themselves
    leans towards whatever else is within reach, and a drawer's front around its handle holds the handle's top
    and sides (fitted, the front of ``moderate_0``'s drawer faced 12 degrees off straight up). Without normals,
    the normal of the plane fitted to them, pointing away from the object's middle. With too few points there,
    the normal of the box face nearest ``position``."""
    close = np.linalg.norm(points - position, axis=1) < radius
    near = points[close]
    if len(near) >= LEAST_POINTS:
        prevailing = None if normals is None else prevailing_direction(normals[close])
        if prevailing is not None:
            return prevailing
        centered = near - near.mean(axis=0)
        normal = np.linalg.svd(centered, full_matrices=False)[2][-1]
        if np.dot(normal, position - points.mean(axis=0)) < 0:
            normal = -normal
        return normal / np.linalg.norm(normal)
    box = fit_box(points)
    gaps = np.concatenate([position - box.lower, box.upper - position])
    k = int(np.argmin(np.abs(gaps)))
    normal = np.zeros(3)
    normal[k % 3] = -1.0 if k < 3 else 1.0
    return normal


def prevailing_direction(normals: np.ndarray, rounds: int = 3) -> np.ndarray | None:
    """The unit direction most of ``normals`` (unit vectors, (N, 3)) point: their mean, narrowed ``rounds``
    times to those within 30 degrees of it, so that a minority facing elsewhere (edges, what stands out of a
    face) does not turn it. None where they cancel out."""
    direction = normals.sum(axis=0)
    for _ in range(rounds):
        length = float(np.linalg.norm(direction))
        if length < 1e-9:
            break
        direction = direction / length
        agreeing = normals @ direction > AGREEING
        if not agreeing.any():
            break
        direction = normals[agreeing].sum(axis=0)
    length = float(np.linalg.norm(direction))
    return None if length < 1e-9 else direction / length
