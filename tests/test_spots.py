"""Free spots, computed for a whole grid at once, match the footprint-by-footprint definition."""

import math

import numpy as np

from roboscript.api.place_requests import _clear_of
from roboscript.api.spots import (
    MARGIN,
    Footprint,
    PlacementSpot,
    gap,
    gaps,
    outline_distances,
    overhang,
    spots_in_receptacle,
)
from roboscript.geometry import Transform, quat_from_yaw
from roboscript.perception.base import Receptacle
from roboscript.perception.footprints import outline_of, rectangle_outline


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


def _boundary(outline: np.ndarray, per_edge: int) -> np.ndarray:
    """Points densely along a closed outline's edges."""
    t = np.linspace(0.0, 1.0, per_edge, endpoint=False)[:, None]
    ends = np.roll(outline, -1, axis=0)
    return np.vstack([a + t * (b - a) for a, b in zip(outline, ends, strict=True)])


def _inside(point: np.ndarray, outline: np.ndarray) -> bool:
    """Whether ``point`` lies within the convex, counter-clockwise ``outline``."""
    edges, offsets = np.roll(outline, -1, axis=0) - outline, point - outline
    return bool(np.all(edges[:, 0] * offsets[:, 1] - edges[:, 1] * offsets[:, 0] >= 0))


def _circle(center, radius: float, count: int = 24) -> np.ndarray:
    angles = np.arange(count) * 2 * math.pi / count
    return np.asarray(center) + radius * np.column_stack([np.cos(angles), np.sin(angles)])


def test_outline_distances_are_as_the_crow_flies_between_outlines_apart_and_negative_where_they_overlap():
    rng = np.random.default_rng(5)
    for _ in range(12):
        own = rectangle_outline(np.zeros(2), rng.uniform(-3, 3), rng.uniform(0.01, 0.06, 2))
        other = _circle(rng.uniform(-0.1, 0.1, 2), rng.uniform(0.01, 0.06))
        centers = rng.uniform(-0.3, 0.3, (6, 2))
        found = outline_distances(centers, own, other)
        for center, distance in zip(centers, found, strict=True):
            a, b = _boundary(own + center, 100), _boundary(other, 30)
            nearest = np.sqrt(((a[:, None] - b[None]) ** 2).sum(axis=-1)).min()
            if distance > 0:
                assert abs(distance - nearest) < 1e-3
            else:  # overlapping: their edges meet, or one holds the other
                assert nearest < 1e-3 or _inside(own[0] + center, other) or _inside(other[0], own + center)
    # Two squares corner to corner: the separating axis says 4 cm, the crow flies 5.7.
    square = rectangle_outline(np.zeros(2), 0.0, np.array([0.05, 0.05]))
    apart = outline_distances(np.array([[0.14, 0.14]]), square, square)[0]
    assert abs(apart - 0.04 * math.sqrt(2)) < 1e-9
    assert (
        gap(
            Footprint(np.array([0.14, 0.14]), 0.0, np.array([0.05, 0.05])),
            Footprint(np.zeros(2), 0.0, np.array([0.05, 0.05])),
        )
        < apart
    )


def test_an_outline_is_the_convex_hull_of_the_points_within_the_footprint_counter_clockwise():
    rng = np.random.default_rng(2)
    angles = rng.uniform(0, 2 * math.pi, 2000)
    disc = np.column_stack([0.04 * np.cos(angles), 0.04 * np.sin(angles), rng.uniform(0.8, 0.9, 2000)])
    stray = np.array([[0.2, 0.2, 0.85]])  # one point of the table taken for the object's
    outline = outline_of(np.vstack([disc, stray]) + np.array([0.3, -0.1, 0.0]))
    assert np.all(np.linalg.norm(outline - [0.3, -0.1], axis=1) <= 0.04 + 1e-9), "the stray point is left out"
    edges = np.roll(outline, -1, axis=0) - outline
    turns = edges[:, 0] * np.roll(edges, -1, axis=0)[:, 1] - edges[:, 1] * np.roll(edges, -1, axis=0)[:, 0]
    assert np.all(turns > 0), "counter-clockwise and convex"
    # Points on a line span no area: the outline is their footprint's rectangle.
    line = np.column_stack([np.linspace(0, 0.1, 20), np.zeros(20), np.zeros(20)])
    assert outline_of(line).shape == (4, 2)


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


def test_spots_in_a_receptacle_keep_clear_of_what_stands_there_by_its_outline_not_its_rectangle():
    """A curved thing's rectangle may cover a plate its outline covers half of (a banana on a round plate)."""
    plate = Receptacle("plate", Transform.identity(), np.array([-0.1, -0.1, 0.0]), np.array([0.1, 0.1, 0.02]))
    half_plate = np.array([[-0.09, -0.09], [0.09, -0.09], [-0.09, 0.09]])  # counter-clockwise
    lying = Footprint(np.zeros(2), 0.0, np.array([0.09, 0.09]), half_plate)
    half, apple = np.array([0.03, 0.03]), _circle(np.zeros(2), 0.03)
    assert spots_in_receptacle(plate, half, 0.0, 0.07, [lying], corner_xy=np.array([-0.5, 0.0])) == []
    spots = spots_in_receptacle(plate, half, 0.0, 0.07, [lying], corner_xy=np.array([-0.5, 0.0]), outline=apple)
    assert spots, "the other half of the plate is free"
    apart = outline_distances(np.array([s.center[:2] for s in spots]), apple, half_plate)
    assert np.all(apart >= MARGIN - 1e-9)


def test_on_a_round_floor_spots_within_it_come_first_and_beyond_it_the_least_beyond():
    """A bottle filled into the corner of the box round a plate's flat middle would stand on the rim and fall over;
    a thing longer than the flat middle goes where the least of it lies beyond."""
    frame = Transform(np.array([0.4, -0.2, 0.8]), quat_from_yaw(0.5))
    box = np.array([-0.08, -0.08, 0.0]), np.array([0.08, 0.08, 0.1])
    round_plate, square_plate = Receptacle("plate", frame, *box, round_floor=True), Receptacle("plate", frame, *box)
    bottle, half = _circle(np.zeros(2), 0.022), np.array([0.022, 0.022])
    corner = np.array([0.0, 0.0])
    for plate, within in ((round_plate, True), (square_plate, False)):
        best = spots_in_receptacle(plate, half, 0.0, 0.09, [], corner_xy=corner, outline=bottle)[0]
        middle = plate.frame.inverse().apply(best.center[None])[0, :2]
        assert (np.linalg.norm(middle) + 0.022 <= 0.08 - MARGIN + 1e-3) == within
        assert overhang(plate, middle[None], bottle)[0] == 0.0 or not within
    long_half = np.array([0.07, 0.03])  # within the box round the flat middle, not within the flat middle
    banana = rectangle_outline(np.zeros(2), 0.0, long_half)
    spots = spots_in_receptacle(round_plate, long_half, 0.5, 0.04, [], corner_xy=corner, outline=banana)
    middle = round_plate.frame.inverse().apply(spots[0].center[None])[0, :2]
    assert np.linalg.norm(middle) < 0.02
    local = np.array([[0.0, 0.0], [0.05, 0.0]])
    assert overhang(round_plate, local, np.zeros((1, 2)))[0] == 0.0
    assert overhang(round_plate, np.array([[0.09, 0.0]]), np.zeros((1, 2)))[0] > 0.0


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
