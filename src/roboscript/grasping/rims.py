"""Pairs across the wall at an open container's rim, read from the ring its top points make.

A mug wider than the gripper's opening can only be taken by its rim, one finger inside the wall and one outside.
The antipodal sampler (:func:`roboscript.grasping.detection.antipodal_pairs`) finds such a pair only where the
cameras saw the inner and the outer face of the wall at the same place, within millimetres: the outer face is seen
from the near side, the inner face over the rim from the far side, and a fused point cloud may hold both at few
places or none (a white mug, 503 points, gave two pairs and no grasp). The rim itself, seen from above, is the
surer sign: its points lie in a ring with nothing in the middle, and each part of the ring gives a pair across
the wall there.
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.perception.base import ObjectPoints

RIM_BAND = 0.012  # metres below the top where a rim's points lie
RIM_WEDGES = 24  # parts of the ring, each giving at most one pair
RIM_WEDGE_POINTS = 4  # fewer points in a part of the ring: too little seen there
RIM_HOLLOW = 0.5  # the ring's points lie beyond this share of its outer radius (a box's top fills its middle)
RIM_HOLLOW_SHARE = 0.05  # of the band's points, at most this many may lie in the middle of a ring
RIM_MAX_WALL = 0.02  # metres: a thicker band is no container's wall
RIM_SEEN_ACROSS = 0.003  # metres: a part of the ring whose points span this much shows the wall's thickness
RIM_GRIP = 0.008  # metres below the rim's top where the pair's middle goes (the grasp search goes deeper)
RIM_QUALITY = 0.5  # contact quality given to a rim pair, that of a middling antipodal pair
FACING = 0.5  # cosine: a point's normal within 60 degrees of a direction faces that way


def rim_pairs(cloud: ObjectPoints, max_width: float) -> list[tuple[np.ndarray, np.ndarray, float, float]]:
    """``(center, closing_axis, quality, width)`` across the wall at each part of an open container's rim that
    the cameras saw, closing along the wall's outward normal there; none where the top is no ring (a box, a
    ball, a can's lid)."""
    points, normals = cloud.points, cloud.normals
    if len(points) < RIM_WEDGES or len(normals) != len(points):
        return []
    top = float(points[:, 2].max())
    in_band = points[:, 2] > top - RIM_BAND
    band, band_normals = points[in_band], normals[in_band]
    # The ring's own middle: the whole object's is off it where a handle juts out below the rim (a mug's, 11 cm
    # across its handle and 8.8 cm across its rim, put it 1.3 cm off, and 8 % of the ring's points within half its
    # radius of that middle made it look filled).
    middle = (band[:, :2].min(axis=0) + band[:, :2].max(axis=0)) / 2
    offset = band[:, :2] - middle
    radius = np.linalg.norm(offset, axis=1)
    if len(band) < RIM_WEDGES or np.mean(radius < RIM_HOLLOW * radius.max()) > RIM_HOLLOW_SHARE:
        return []
    angle = np.arctan2(offset[:, 1], offset[:, 0])
    walls = [_wall(band[w], band_normals[w], middle) for w in _wedges(angle)]
    spans = [w[2] - w[1] for w in walls if w is not None and w[2] - w[1] >= RIM_SEEN_ACROSS]
    if not spans:
        return []  # nowhere was the wall seen across: how thick it is is unknown
    thickness = float(np.median(spans))
    out = []
    for wall in walls:
        if wall is None:
            continue
        closing, inner, outer, outer_seen = wall
        if outer - inner >= RIM_SEEN_ACROSS:
            width, along = outer - inner, (outer + inner) / 2
        else:  # one face seen here: the wall lies behind it, as thick as elsewhere
            width, along = thickness, (outer - thickness / 2 if outer_seen else inner + thickness / 2)
        if width > min(RIM_MAX_WALL, max_width):
            continue
        center_xy = middle + closing * along
        out.append((np.array([*center_xy, top - RIM_GRIP]), np.array([*closing, 0.0]), RIM_QUALITY, width))
    return out


def _wedges(angle: np.ndarray) -> list[np.ndarray]:
    """Masks of the band's points in each of :data:`RIM_WEDGES` equal parts of the turn about the middle."""
    half = math.pi / RIM_WEDGES
    masks = []
    for k in range(RIM_WEDGES):
        theta = 2 * math.pi * k / RIM_WEDGES
        masks.append(np.abs(np.remainder(angle - theta + math.pi, 2 * math.pi) - math.pi) < half)
    return masks


def _wall(points: np.ndarray, normals: np.ndarray, middle: np.ndarray) -> tuple[np.ndarray, float, float, bool] | None:
    """The wall in one part of the ring: its outward normal (horizontal, unit), the nearest and farthest of its
    points from the middle along that normal, and whether more of them face out than in (the outer face is the
    one seen); None where too little was seen."""
    if len(points) < RIM_WEDGE_POINTS:
        return None
    radial = np.mean(points[:, :2] - middle, axis=0)
    radial /= max(float(np.linalg.norm(radial)), 1e-9)
    flat = normals[:, :2]
    outward = flat @ radial > FACING
    inward = flat @ radial < -FACING
    # The outer face's normals give the wall's direction where it is not round (a square cup's side).
    closing = np.mean(flat[outward], axis=0) if outward.sum() >= 2 else radial
    closing /= max(float(np.linalg.norm(closing)), 1e-9)
    along = (points[:, :2] - middle) @ closing
    return closing, float(along.min()), float(along.max()), bool(outward.sum() >= inward.sum())
