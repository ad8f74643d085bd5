"""A cabinet's side and back panels are laid where its seen points put them, up to its top's front edge, in its
own frame, whichever way it faces; its inside, what lies before its front and an open drawer standing out of it
stay free."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.perception.furniture.carcass import carcass_frame, carcass_panels
from roboscript.perception.furniture.compartments import PANEL

CENTRE = np.array([0.5, 0.2, 0.0])


def _seen(yaw: float, drawer_out: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points and normals of what cameras see of a 0.36 deep, 0.4 wide carcass, 0.82 to 1.22 high, at (0.5, 0.2)
    facing ``yaw``: its top and its front, not its sides or its back; with ``drawer_out``, a drawer's tray pulled
    that far out of its front at mid height (its points go with the carcass's)."""
    rng = np.random.default_rng(0)
    n = 800
    top = np.column_stack([rng.uniform(-0.18, 0.18, n), rng.uniform(-0.2, 0.2, n), np.full(n, 1.22)])
    front = np.column_stack([np.full(n, 0.18), rng.uniform(-0.2, 0.2, n), rng.uniform(0.82, 1.22, n)])
    points, normals = [top, front], [np.tile([0.0, 0.0, 1.0], (n, 1)), np.tile([1.0, 0.0, 0.0], (n, 1))]
    if drawer_out:
        tray = np.column_stack([rng.uniform(0.18, 0.18 + drawer_out, n), rng.uniform(-0.18, 0.18, n), np.full(n, 1.0)])
        points.append(tray)
        normals.append(np.tile([0.0, 0.0, 1.0], (n, 1)))  # the tray's bottom faces up too, lower than the top
    facing = np.array([np.cos(yaw), np.sin(yaw), 0.0])
    rotation = carcass_frame(facing)
    return np.vstack(points) @ rotation.T + CENTRE, np.vstack(normals) @ rotation.T, facing


def _local(panels: np.ndarray, facing: np.ndarray) -> np.ndarray:
    return (panels - CENTRE) @ carcass_frame(facing)


@pytest.mark.parametrize("yaw", [0.0, -np.pi / 2, np.radians(30)])
def test_the_panels_stand_inside_the_edges_of_the_top(yaw):
    points, normals, facing = _seen(yaw)
    local = _local(carcass_panels(points, normals, facing), facing)
    on_a_side = np.abs(np.abs(local[:, 1]) - 0.2) <= PANEL + 0.006
    at_the_back = np.abs(local[:, 0] + 0.18) <= PANEL + 0.006
    assert np.all(on_a_side | at_the_back)  # nothing inside the carcass, where things are put
    assert np.all(local[:, 0] <= 0.18 + 0.006)  # nothing before its front
    for side in (-0.2, 0.2):  # each side covered from back to front, bottom to top
        half = local[np.abs(local[:, 1] - side) <= PANEL + 0.006]
        assert half[:, 0].min() < -0.17 and half[:, 0].max() > 0.17
        assert half[:, 2].min() < 0.83 and half[:, 2].max() > 1.21
        assert np.all(np.diff(np.unique(np.round(half[:, 2], 4))) <= 0.0101)  # no gap a thin thing passes through


def test_an_open_drawer_standing_out_of_the_front_does_not_carry_the_sides_out():
    points, normals, facing = _seen(0.0, drawer_out=0.15)
    local = _local(carcass_panels(points, normals, facing), facing)
    assert local[:, 0].max() <= 0.18 + 0.006


def test_a_top_seen_too_little_lays_no_panel_and_a_vertical_front_is_refused():
    points, _, facing = _seen(0.0)
    sideways = np.tile([1.0, 0.0, 0.0], (len(points), 1))  # nothing faces up: no top was seen
    assert carcass_panels(points, sideways, facing).shape == (0, 3)
    with pytest.raises(ValueError, match="horizontal direction"):
        carcass_frame(np.array([0.0, 0.0, 1.0]))
