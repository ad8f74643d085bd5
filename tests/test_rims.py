"""Pairs across an open container's rim, from the ring its top points make (clouds built in the test)."""

import math

import numpy as np

from roboscript.grasping.detection import GripperGeometry, detect_grasps
from roboscript.grasping.rims import rim_pairs
from roboscript.perception.base import ObjectPoints


def _ring(radius: float, z_low: float, z_high: float, facing: float, angles=(0.0, 2 * math.pi), spacing=0.004):
    """Points on a vertical cylinder's face, normals outward (``facing`` 1) or inward (-1), over ``angles``."""
    points, normals = [], []
    turns = int(2 * math.pi * radius / spacing)
    for k in range(turns):
        a = 2 * math.pi * k / turns
        if not angles[0] <= a < angles[1]:
            continue
        for z in np.arange(z_low, z_high + 1e-9, spacing):
            points.append([radius * math.cos(a), radius * math.sin(a), z])
            normals.append([facing * math.cos(a), facing * math.sin(a), 0.0])
    return points, normals


def _mug(inner_seen=(math.pi / 2, 3 * math.pi / 2)):
    """An 8.8 cm mug 9.5 cm tall with a 6 mm wall: its outer face all round, its rim's top, its inner face only
    over ``inner_seen`` (seen over the rim from one side)."""
    outer, outer_n = _ring(0.044, 0.82, 0.915, 1.0)
    inner, inner_n = _ring(0.038, 0.85, 0.915, -1.0, inner_seen)
    top, top_n = [], []
    for r in (0.039, 0.041, 0.043):
        ring, _ = _ring(r, 0.915, 0.915, 1.0)
        top += ring
        top_n += [[0.0, 0.0, 1.0]] * len(ring)
    return ObjectPoints(np.array(outer + inner + top), np.array(outer_n + inner_n + top_n))


def test_a_mug_wider_than_the_opening_gets_pairs_across_its_wall_all_round():
    pairs = rim_pairs(_mug(), 0.077)
    assert len(pairs) >= 20
    for center, closing, _, width in pairs:
        radial = center[:2] / np.linalg.norm(center[:2])
        assert abs(float(closing[:2] @ radial)) > 0.95  # across the wall
        assert 0.035 < np.linalg.norm(center[:2]) < 0.045
        assert 0.003 <= width <= 0.008
        assert 0.9 < center[2] < 0.915


def test_the_rim_pairs_give_grasps_where_the_inner_face_is_seen_nowhere_across():
    # Where the inner face is seen only on one side, the sampler finds a pair there at best; the rim gives them
    # all round, and the detector turns them into grasps that close on the wall.
    mug = _mug(inner_seen=(0.0, 0.0))
    assert rim_pairs(mug, 0.077)  # the rim's top spans the wall's thickness
    xs = np.arange(-0.2, 0.2, 0.01)
    table = np.array([[x, y, 0.82] for x in xs for y in xs])
    grasps = detect_grasps(mug, np.vstack([mug.points, table]), GripperGeometry(0.08), seed=0)
    assert grasps
    assert all(g.width < 0.02 for g in grasps[:5])


def test_a_box_top_is_no_rim():
    xs = np.arange(-0.03, 0.03 + 1e-9, 0.004)
    top = np.array([[x, y, 0.9] for x in xs for y in xs])
    sides, side_n = _ring(0.03, 0.82, 0.9, 1.0)
    points = np.vstack([top, np.array(sides)])
    normals = np.vstack([np.tile([0.0, 0.0, 1.0], (len(top), 1)), np.array(side_n)])
    assert rim_pairs(ObjectPoints(points, normals), 0.077) == []


def _handle(reach: float = 0.075):
    """A mug's handle: a loop jutting out along +x from the outer face, below the rim."""
    points = [[x, y, z] for x in np.arange(0.044, reach, 0.004) for y in (-0.006, 0.006) for z in (0.845, 0.89)]
    points += [[reach, y, z] for y in (-0.006, 0.006) for z in np.arange(0.845, 0.89, 0.004)]
    normals = [[0.0, math.copysign(1.0, p[1]), 0.0] for p in points]
    return np.array(points), np.array(normals)


def test_a_handle_below_the_rim_does_not_move_the_ring_off_its_middle():
    # The whole mug's box reaches out to the handle's end; the ring is read about its own middle, so its points
    # are all far from it and every pair closes across the wall where it is.
    mug = _mug()
    handle, handle_n = _handle()
    with_handle = ObjectPoints(np.vstack([mug.points, handle]), np.vstack([mug.normals, handle_n]))
    pairs = rim_pairs(with_handle, 0.077)
    assert len(pairs) >= 20
    for center, _, _, _ in pairs:
        assert 0.035 < np.linalg.norm(center[:2]) < 0.045
