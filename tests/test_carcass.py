"""A cabinet's side and back panels are laid where its seen points put them, in its own frame, whichever way it
faces; its inside and what lies before its front stay free."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.perception.carcass import carcass_frame, carcass_panels
from roboscript.perception.compartments import PANEL


def _seen_top_and_front(yaw: float) -> tuple[np.ndarray, np.ndarray]:
    """What cameras see of a 0.36 deep, 0.4 wide, 0.4 high carcass at (0.5, 0.2) facing ``yaw``: its top and its
    front, not its sides or its back."""
    rng = np.random.default_rng(0)
    top = np.column_stack([rng.uniform(-0.18, 0.18, 800), rng.uniform(-0.2, 0.2, 800), np.full(800, 1.22)])
    front = np.column_stack([np.full(800, 0.18), rng.uniform(-0.2, 0.2, 800), rng.uniform(0.82, 1.22, 800)])
    facing = np.array([np.cos(yaw), np.sin(yaw), 0.0])
    rotation = carcass_frame(facing)
    return np.vstack([top, front]) @ rotation.T + np.array([0.5, 0.2, 0.0]), facing


@pytest.mark.parametrize("yaw", [0.0, -np.pi / 2, np.radians(30)])
def test_the_panels_stand_inside_the_faces_the_seen_points_reach(yaw):
    points, facing = _seen_top_and_front(yaw)
    panels = carcass_panels(points, facing)
    local = (panels - np.array([0.5, 0.2, 0.0])) @ carcass_frame(facing)
    on_a_side = np.abs(np.abs(local[:, 1]) - 0.2) <= PANEL + 0.006
    at_the_back = np.abs(local[:, 0] + 0.18) <= PANEL + 0.006
    assert np.all(on_a_side | at_the_back)  # nothing inside the carcass, where things are put
    assert np.all(local[:, 0] <= 0.18 + 0.006)  # nothing before its front
    for side in (-0.2, 0.2):  # each side covered from back to front, bottom to top
        half = local[np.abs(local[:, 1] - side) <= PANEL + 0.006]
        assert half[:, 0].min() < -0.17 and half[:, 0].max() > 0.17
        assert half[:, 2].min() < 0.83 and half[:, 2].max() > 1.21
        assert np.all(np.diff(np.unique(np.round(half[:, 2], 4))) <= 0.0101)  # no gap a thin thing passes through


def test_too_little_seen_lays_no_panel_and_a_vertical_front_is_refused():
    assert carcass_panels(np.zeros((5, 3)), np.array([1.0, 0.0, 0.0])).shape == (0, 3)
    with pytest.raises(ValueError, match="horizontal direction"):
        carcass_frame(np.array([0.0, 0.0, 1.0]))
