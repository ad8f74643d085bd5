"""How wide a grasp must open: across what the cameras see of the object and, for a box, across its footprint's
corners, which they sample thinly or not at all (a round thing's rectangle overstates it); and the grasps from
above turned off square where the object is narrow enough that way."""

from __future__ import annotations

import math

import numpy as np
import pytest

from roboscript.geometry import Box3D
from roboscript.grasping.heuristics import GraspError, Outline, central_lift_grasps, horizontal_grasps
from roboscript.perception.base import ObjectPoints

MAX_WIDTH = 0.085  # the 2F-85's opening
BASE = np.array([0.0, 0.0])
CENTER = np.array([-0.37, 0.41])


class _Seen:
    """Test double: one object on the table (at z 0.82) whose points are ``points``, with its footprint
    rectangle and box as perception would give them."""

    def __init__(self, points: np.ndarray, yaw: float, half: np.ndarray, height: float):
        self.cloud, self.yaw, self.half = points, yaw, half
        corners = np.array([[sx * half[0], sy * half[1]] for sx in (-1, 1) for sy in (-1, 1)])
        c, s = math.cos(yaw), math.sin(yaw)
        xy = corners @ np.array([[c, s], [-s, c]]) + CENTER
        self.outline = Box3D(np.array([*xy.min(axis=0), 0.82]), np.array([*xy.max(axis=0), 0.82 + height]))

    def box(self, name):
        return self.outline

    def points(self, name):
        return ObjectPoints(self.cloud, np.tile([0.0, 0.0, 1.0], (len(self.cloud), 1)))

    def footprint(self, name):
        return CENTER, self.yaw, self.half


def _top_face(yaw: float, half: np.ndarray, height: float, keep) -> np.ndarray:
    """Points on a grid over the footprint's top face, those ``keep`` (local x, y) accepts."""
    grid = [(x, y) for x in np.linspace(-half[0], half[0], 21) for y in np.linspace(-half[1], half[1], 9)]
    local = np.array([p for p in grid if keep(*p)])
    c, s = math.cos(yaw), math.sin(yaw)
    xy = local @ np.array([[c, s], [-s, c]]) + CENTER
    return np.column_stack([xy, np.full(len(xy), 0.82 + height)])


def _across(yaw: float, half: np.ndarray, direction: np.ndarray) -> float:
    """How wide the turned rectangle is along ``direction``."""
    along = np.array([math.cos(yaw), math.sin(yaw)]) @ direction[:2]
    side = np.array([-math.sin(yaw), math.cos(yaw)]) @ direction[:2]
    return 2 * (half[0] * abs(along) + half[1] * abs(side))


def test_a_box_is_gripped_only_where_its_footprint_fits_between_the_fingers_whatever_corners_were_seen():
    yaw, half = math.radians(72), np.array([0.05, 0.02])  # a 10 x 4 cm bar, 4 cm high
    # Its far corners unseen: the points alone are narrower than the bar slantwise.
    points = _top_face(yaw, half, 0.04, lambda x, y: abs(x) + 0.6 * abs(y) < 0.052)
    seen = _Seen(points, yaw, half, 0.04)
    grasps = horizontal_grasps(seen, "wooden_bar", None, MAX_WIDTH, BASE)
    assert grasps
    assert all(_across(yaw, half, g.rotation[:, 1]) <= MAX_WIDTH - 0.003 for g in grasps)
    outline = Outline.of(seen, "wooden_bar", points)
    assert outline.box_like
    slantwise = np.array([math.cos(math.radians(129)), math.sin(math.radians(129)), 0.0])
    assert outline.across(slantwise) == pytest.approx(_across(yaw, half, slantwise))
    assert outline.across(slantwise) > MAX_WIDTH  # 57 degrees off the bar's length: 8.8 cm


def test_a_round_thing_is_gripped_across_what_is_seen_not_across_its_rectangles_diagonal():
    half = np.array([0.04, 0.04])  # a disc 8 cm across: its rectangle is 11.3 cm corner to corner
    points = _top_face(0.0, half, 0.03, lambda x, y: x * x + y * y <= 0.04**2)
    seen = _Seen(points, 0.0, half, 0.03)
    assert not Outline.of(seen, "orange", points).box_like
    grasps = horizontal_grasps(seen, "orange", None, MAX_WIDTH, BASE)
    headings = {round(math.degrees(math.atan2(g.rotation[1, 1], g.rotation[0, 1]))) % 180 for g in grasps}
    assert any(h % 90 not in (0,) and abs(h % 90 - 45) < 30 for h in headings)  # slantwise to the rectangle too


def test_grasps_from_above_come_square_first_then_turned_where_the_box_is_narrow_enough_that_way():
    half = np.array([0.0285, 0.0285])  # a Rubik's cube, 5.7 cm
    cube = _Seen(_top_face(0.0, half, 0.057, lambda x, y: True), 0.0, half, 0.057)
    grasps = central_lift_grasps(cube, "rubiks_cube", "center", 0.08, BASE)
    turns = [round(math.degrees(math.atan2(g.rotation[1, 1], g.rotation[0, 1]))) % 90 for g in grasps]
    square = [t in (0, 90) for t in turns]
    assert square[0] and square.index(False) == sum(square)  # every square grasp before any turned one
    assert {15, 75} <= set(turns)  # 15 degrees either way: 7.0 cm across
    assert 30 not in turns and 60 not in turns  # 30 degrees: 7.8 cm, more than the 8 cm opening less its margin
    half = np.array([0.045, 0.036])  # 9 x 7.2 cm: turned 15 degrees it is 9.3 cm across
    box = _Seen(_top_face(0.0, half, 0.05, lambda x, y: True), 0.0, half, 0.05)
    assert all(abs(g.rotation[0, 1]) < 1e-9 for g in central_lift_grasps(box, "brown_box", "center", 0.08, BASE))


def test_a_round_thing_wider_than_the_opening_is_not_gripped_slantwise_where_its_far_side_is_unseen():
    half = np.array([0.043, 0.043])  # a tuna can 8.6 cm across, the 2F-85 opening 8.5
    near_half = _top_face(0.0, half, 0.034, lambda x, y: x * x + y * y <= 0.043**2 and x + y < 0.0)
    can = _Seen(near_half, 0.0, half, 0.034)
    with pytest.raises(GraspError, match="wider than the gripper"):
        central_lift_grasps(can, "tuna_can", "center", MAX_WIDTH, BASE)


def test_the_far_turns_come_round_the_object_beyond_the_near_ones_square_to_its_sides_among_them():
    """A cube nearly as wide as the opening, a bowl beside it on the robot's side: the near approaches are all
    blocked, so the tool asks for the turns beyond them, which include the side-on ones out there."""
    yaw, half = math.radians(47), np.array([0.038, 0.038])  # square to one side 85 degrees off the heading
    points = _top_face(yaw, half, 0.057, lambda x, y: True)
    seen = _Seen(points, yaw, half, 0.057)
    heading = math.atan2(CENTER[1] - BASE[1], CENTER[0] - BASE[0])

    def turns(grasps):
        approaches = [g.rotation[:, 2] for g in grasps]
        return {round(math.remainder(math.atan2(a[1], a[0]) - heading, 2 * math.pi), 2) for a in approaches}

    near = turns(horizontal_grasps(seen, "rubiks_cube", None, 0.08, BASE))
    far = turns(horizontal_grasps(seen, "rubiks_cube", None, 0.08, BASE, far=True))
    assert max(abs(t) for t in near) <= 1.31
    assert far and min(abs(t) for t in far) > 1.3 and max(abs(t) for t in far) <= 1.91
    side_on = [t for t in far if abs(math.remainder(t + heading - yaw, math.pi / 2)) < 0.02]
    assert side_on  # closing square across the cube: the only way it fits between the fingers
