"""Free spots, computed for a whole grid at once, match the footprint-by-footprint definition."""

import math

import numpy as np

from roboscript.api.place_requests import _clear_of
from roboscript.api.spots import Footprint, PlacementSpot, gap, gaps, spots_in_receptacle
from roboscript.geometry import Transform, quat_from_yaw
from roboscript.perception.base import Receptacle


def _gap_by_definition(a: Footprint, b: Footprint) -> float:
    """The separating-axis gap, one axis at a time."""
    best = -math.inf
    for axis in np.vstack([a.axes(), b.axes()]):
        pa, pb = a.corners() @ axis, b.corners() @ axis
        best = max(best, float(pb.min() - pa.max()), float(pa.min() - pb.max()))
    return best


def test_gaps_of_many_footprints_are_each_ones_gap():
    rng = np.random.default_rng(3)
    for _ in range(50):
        other = Footprint(rng.uniform(-0.2, 0.2, 2), rng.uniform(-3, 3), rng.uniform(0.01, 0.1, 2))
        yaw, half = rng.uniform(-3, 3), rng.uniform(0.01, 0.1, 2)
        centers = rng.uniform(-0.3, 0.3, (40, 2))
        expected = [_gap_by_definition(Footprint(c, yaw, half), other) for c in centers]
        np.testing.assert_allclose(gaps(centers, yaw, half, other), expected, atol=1e-12)
        assert abs(gap(Footprint(centers[0], yaw, half), other) - expected[0]) < 1e-12
    overlapping = Footprint(np.zeros(2), 0.3, np.array([0.05, 0.02]))
    assert gap(overlapping, Footprint(np.array([0.01, 0.0]), 1.0, np.array([0.03, 0.03]))) < 0


def test_spots_in_a_turned_tray_keep_clear_of_what_is_in_it():
    tray = Receptacle(
        "tray",
        Transform(np.array([0.5, 0.1, 0.8]), quat_from_yaw(0.4)),
        np.array([-0.15, -0.1, 0.0]),
        np.array([0.15, 0.1, 0.05]),
    )
    mug = Footprint(np.array([0.52, 0.12]), 0.9, np.array([0.04, 0.03]))
    half = np.array([0.03, 0.02])
    spots = spots_in_receptacle(tray, half, 0.2, 0.06, [mug], corner_xy=np.array([0.3, 0.0]))
    assert len(spots) > 20
    scores = [s.score for s in spots]
    assert scores == sorted(scores, reverse=True)
    local = tray.frame.inverse().apply(np.array([s.center for s in spots]))
    assert np.all(local[:, :2] >= tray.lower[:2] + half.min() - 1e-9) and np.all(
        local[:, :2] <= tray.upper[:2] - half.min() + 1e-9
    )
    for s in spots:  # every spot, turned as it will be placed, clears the mug by the margin
        turned = Footprint(s.center[:2], 0.2 + s.yaw, half + 0.007)
        assert _gap_by_definition(turned, mug) >= -1e-9
    # Without the mug, spots where it stands become free.
    assert len(spots_in_receptacle(tray, half, 0.2, 0.06, [], corner_xy=np.array([0.3, 0.0]))) > len(spots)


def test_spots_clear_of_points_are_those_with_no_point_within_the_radius():
    rng = np.random.default_rng(5)
    points = np.column_stack([rng.uniform(0, 1, (3000, 2)), rng.uniform(0.75, 1.4, 3000)])
    spots = [PlacementSpot(np.array([x, y, 0.837]), 0.0, 0.0) for x, y in rng.uniform(-0.1, 1.1, (300, 2))]
    radius, table_top = 0.03, 0.8
    band = points[(points[:, 2] > table_top + 0.005) & (points[:, 2] < table_top + 0.5)][:, :2]
    expected = [s for s in spots if np.min(np.linalg.norm(band - s.center[:2], axis=1)) > radius]
    kept = _clear_of(spots, points, radius, table_top)
    assert 0 < len(kept) < len(spots)
    assert [id(s) for s in kept] == [id(s) for s in expected]
