"""Carving: the fill under an object's seen surfaces goes where a camera that shows the object sees through it."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Transform, quat_from_yaw
from roboscript.perception.reconstruction.carving import SHELL, seen_through
from roboscript.planning.perceived_scene import filled_below
from roboscript.robot_io import CameraFrame


def _frame(depth: np.ndarray) -> CameraFrame:
    """A 100x100 camera at the origin looking along +z, its depth image given."""
    k = np.array([[100.0, 0, 50], [0, 100.0, 50], [0, 0, 1]])
    rgb = np.zeros((100, 100, 3), dtype=np.uint8)
    return CameraFrame("test", rgb, depth.astype(np.float32), None, k, Transform(np.zeros(3), quat_from_yaw(0.0)))


def _object_and_wall() -> np.ndarray:
    """An object's face 0.5 m away on the image's left half, a wall 1 m away on the right half."""
    depth = np.ones((100, 100))
    depth[:, :50] = 0.5
    return depth


def test_fill_that_a_view_showing_the_object_sees_through_is_free():
    frame = _frame(_object_and_wall())
    surface = np.array([[-0.1, 0.0, 0.5], [-0.2, 0.1, 0.5]])  # seen again on the left half
    fill = np.array(
        [
            [0.1, 0.0, 0.5],  # right half, the wall 0.5 m beyond it: seen through
            [0.1, 0.0, 0.99],  # right half, 1 cm in front of the wall: not clearly beyond
            [-0.1, 0.0, 0.7],  # left half, behind the object's face: hidden
            [5.0, 0.0, 1.0],  # out of the image
        ]
    )
    assert seen_through(fill, surface, [frame], [None]).tolist() == [True, False, False, False]
    robot = np.zeros((100, 100), dtype=bool)
    robot[:, 50:] = True  # the robot's own pixels say nothing of what is behind them
    assert not seen_through(fill, surface, [frame], [robot]).any()


def test_a_view_that_does_not_show_the_object_where_it_is_does_not_judge_its_fill():
    # Carried since that look: the view sees the wall through where the object's points are now.
    frame = _frame(_object_and_wall())
    moved_surface = np.array([[0.1, 0.0, 0.5], [0.2, 0.1, 0.5]])
    fill = np.array([[0.1, 0.05, 0.55]])
    assert not seen_through(fill, moved_surface, [frame], [None]).any()


def test_the_fill_a_view_sees_through_goes_but_a_shell_under_the_seen_surface_stays():
    top = np.array([[0.0025, 0.0025, 0.10]])  # one column, seen at 10 cm over a floor at 0
    everything_free = filled_below(top, 0.0, seen_free=lambda fill: np.ones(len(fill), dtype=bool))
    nothing_free = filled_below(top, 0.0)
    assert len(nothing_free) == 1 + 20  # the seen point and the fill, every 5 mm down to the floor
    heights = everything_free[1:, 2]
    assert len(heights) and heights.min() >= 0.10 - SHELL - 1e-9  # only the shell is left under the top
