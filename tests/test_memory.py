"""Occupancy memory: what the robot hides from a camera is remembered, what a camera sees through is forgotten."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Transform, quat_from_yaw
from roboscript.perception.reconstruction.memory import remembered
from roboscript.robot_io import CameraFrame


def _frame() -> CameraFrame:
    """A 100x100 camera at the origin looking along +z at a wall 1 m away."""
    k = np.array([[100.0, 0, 50], [0, 100.0, 50], [0, 0, 1]])
    depth = np.ones((100, 100), dtype=np.float32)
    rgb = np.zeros((100, 100, 3), dtype=np.uint8)
    return CameraFrame("test", rgb, depth, None, k, Transform(np.zeros(3), quat_from_yaw(0.0)))


def test_hidden_points_stay_and_seen_through_or_seen_again_points_go():
    frame = _frame()
    robot = np.zeros((100, 100), dtype=bool)
    robot[:, :50] = True  # the robot covers the left half of the image
    old = np.array(
        [
            [-0.1, 0.0, 0.5],  # left half, behind the robot's pixels: kept
            [0.1, 0.0, 0.5],  # right half, in front of the wall: the camera sees through it, so it has gone
            [0.1, 0.1, 1.0],  # on the wall: seen again (the new look has it)
            [0.1, -0.1, 1.5],  # behind the wall: hidden, kept
            [5.0, 0.0, 1.0],  # out of the image: kept
        ]
    )
    kept = remembered(old, [frame], [robot])
    assert np.array_equal(kept, old[[0, 3, 4]])
    assert np.array_equal(remembered(old, [frame], [None]), old[[3, 4]])  # without a mask nothing hides
    assert remembered(np.zeros((0, 3)), [frame], [None]).shape == (0, 3)
