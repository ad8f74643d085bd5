"""Whether a look shows a place empty: a camera straight above a floor sees a patch of points, sees through where
they were, is blocked in front of them, or has the robot in the way; and what a camera at the side sees through
under a patch is no solid under it."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Transform
from roboscript.perception.free_space import THROUGH, carved, seen_through, stands_empty
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


def _side(depth: float) -> CameraFrame:
    """A camera 1 m along x from the patch, 5 cm above the floor, looking back along -x, seeing ``depth`` everywhere."""
    intrinsics = np.array([[100.0, 0.0, 40.0], [0.0, 100.0, 30.0], [0.0, 0.0, 1.0]])
    looking = np.array([[0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])  # right: +y, down: -z, ahead: -x
    pose = Transform.from_rotation(np.array([1.0, 0.0, 0.05]), looking)
    return CameraFrame("side", None, np.full((H, W), depth, np.float32), None, intrinsics, pose)


def _under_the_patch() -> np.ndarray:
    x, y, z = np.meshgrid(np.linspace(-0.05, 0.05, 6), np.linspace(-0.05, 0.05, 6), np.linspace(0.02, 0.09, 8))
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()])


def test_what_a_side_camera_sees_through_under_a_patch_is_carved_from_its_fill():
    """A rim seen from above (a bowl's): a camera at the side sees the wall far behind, under the rim, so nothing
    solid stands there; one that sees something just beyond the fill (a foot) carves nothing."""
    above = np.full((H, W), 1.0)
    above[20:41, 30:51] = 0.9
    fill = _under_the_patch()
    frames = [_frame(above), _side(2.0)]
    kept = carved(_patch(), fill, frames, [None, None])
    assert np.all(kept[:, 2] >= 0.1 - THROUGH)  # only what lies within the depth's tolerance of the rim stays
    assert len(kept) < len(fill) / 4
    frames = [_frame(above), _side(0.94)]  # a surface just before the fill: it hides the fill, tells nothing
    assert len(carved(_patch(), fill, frames, [None, None])) == len(fill)


def test_a_look_that_does_not_show_the_surface_where_it_is_carves_nothing():
    """The object moved since the look (it was let go elsewhere): the look sees through its surface, and says
    nothing of what is under it now."""
    fill = _under_the_patch()
    frames = [_frame(np.full((H, W), 1.0)), _side(2.0)]
    assert len(carved(_patch(), fill, frames, [None, None])) == len(fill)
