"""Whether a look shows a place empty: a camera straight above a floor sees a patch of points, sees through where
they were, is blocked in front of them, or has the robot in the way."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Transform
from roboscript.perception.reconstruction.free_space import seen_through, stands_empty
from roboscript.robot_io import CameraFrame

H, W = 60, 80


def _frame(depth: np.ndarray) -> CameraFrame:
    """A camera 1 m above the floor looking straight down."""
    intrinsics = np.array([[100.0, 0.0, 40.0], [0.0, 100.0, 30.0], [0.0, 0.0, 1.0]])
    pose = Transform.from_rotation(np.array([0.0, 0.0, 1.0]), np.diag([1.0, -1.0, -1.0]))
    return CameraFrame("above", None, depth.astype(np.float32), None, intrinsics, pose)


def _patch() -> np.ndarray:
    """Points of a 10 cm square 10 cm above the floor (0.9 m from the camera)."""
    x, y = np.meshgrid(np.linspace(-0.05, 0.05, 11), np.linspace(-0.05, 0.05, 11))
    return np.column_stack([x.ravel(), y.ravel(), np.full(x.size, 0.1)])


def test_a_floor_seen_where_the_patch_was_shows_the_place_empty():
    points = _patch()
    through, seen = seen_through(points, [_frame(np.full((H, W), 1.0))], [None])
    assert through.all() and not seen.any()
    assert stands_empty(points, [_frame(np.full((H, W), 1.0))], [None])


def test_the_patch_still_there_is_seen_not_seen_through():
    depth = np.full((H, W), 1.0)
    depth[20:41, 30:51] = 0.9
    through, seen = seen_through(_patch(), [_frame(depth)], [None])
    assert seen.all() and not through.any()
    assert not stands_empty(_patch(), [_frame(depth)], [None])


def test_what_is_hidden_in_front_or_by_the_robot_tells_nothing():
    in_front = _frame(np.full((H, W), 0.5))
    assert not stands_empty(_patch(), [in_front], [None])
    robot = np.ones((H, W), dtype=bool)
    assert not stands_empty(_patch(), [_frame(np.full((H, W), 1.0))], [robot])
    no_depth = _frame(np.zeros((H, W)))
    assert not stands_empty(_patch(), [no_depth], [None])


def test_a_point_one_view_sees_counts_as_there_though_another_sees_through_it():
    depth = np.full((H, W), 1.0)
    depth[20:41, 30:51] = 0.9
    assert not stands_empty(_patch(), [_frame(np.full((H, W), 1.0)), _frame(depth)], [None, None])
