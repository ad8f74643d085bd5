"""The rules that turn an object's points into its own: the skirt of a support beside it, what a smaller object
claims, what an object rests on. Synthetic points, so that each rule is seen alone."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.instances import (
    Instance3D,
    _claimed_by,
    ground,
    object_box,
    without_skirt,
)

TABLE = 0.8


def _grid(x: tuple[float, float], y: tuple[float, float], z: float, step: float = 0.004) -> np.ndarray:
    xs, ys = np.meshgrid(np.arange(*x, step), np.arange(*y, step))
    return np.column_stack([xs.ravel(), ys.ravel(), np.full(xs.size, z)])


def _box_surface(lower: np.ndarray, upper: np.ndarray, step: float = 0.004) -> np.ndarray:
    """The top and the four sides of a box, as cameras from above and around see it."""
    top = _grid((lower[0], upper[0]), (lower[1], upper[1]), upper[2], step)
    sides = []
    for z in np.arange(lower[2], upper[2], step):
        for x in np.arange(lower[0], upper[0], step):
            sides += [[x, lower[1], z], [x, upper[1], z]]
        for y in np.arange(lower[1], upper[1], step):
            sides += [[lower[0], y, z], [upper[0], y, z]]
    return np.vstack([top, np.array(sides)])


def test_a_plate_beside_a_box_lying_on_it_is_no_part_of_the_box():
    floor = TABLE + 0.008  # the plate's floor, where the box lies
    box = _box_surface(np.array([-0.045, -0.035, floor]), np.array([0.045, 0.035, floor + 0.028]))
    plate = _grid((-0.09, 0.09), (-0.09, 0.09), floor)
    plate = plate[(np.abs(plate[:, 0]) > 0.05) | (np.abs(plate[:, 1]) > 0.04)]  # the part the box leaves in view
    points = np.vstack([box, plate])
    kept = points[without_skirt(points)]
    assert np.all(np.abs(kept[:, 0]) < 0.045 + 0.006) and np.all(np.abs(kept[:, 1]) < 0.035 + 0.006)
    assert len(kept) >= len(box) * 0.95  # the box's own foot stays


def test_a_plate_and_a_bowl_keep_all_their_points():
    plate = _grid((-0.1, 0.1), (-0.1, 0.1), TABLE + 0.006)
    assert len(without_skirt(plate)) == len(plate)  # all in the band: nothing over it to outline it
    angles = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    rim = np.column_stack([0.08 * np.cos(angles), 0.08 * np.sin(angles), np.full(200, TABLE + 0.06)])
    bowl = np.vstack([rim, _grid((-0.05, 0.05), (-0.05, 0.05), TABLE + 0.005)])
    assert len(without_skirt(bowl)) == len(bowl)  # its floor lies inside its rim's outline


def test_a_box_on_a_plate_rests_on_it_and_keeps_its_bottom():
    plate = Instance3D(
        "plate", np.zeros((0, 3)), np.zeros((0, 3)), Box3D(np.r_[-0.1, -0.1, TABLE], np.r_[0.1, 0.1, 0.82]), (0,)
    )
    lying = Box3D(np.r_[-0.04, -0.03, TABLE + 0.008], np.r_[0.04, 0.03, TABLE + 0.036])
    box = Instance3D("gelatin box", np.zeros((0, 3)), np.zeros((0, 3)), lying, (0,))
    grounded = ground([plate, box], TABLE)
    assert grounded[1].box.lower[2] == TABLE + 0.008  # below the plate's rim, on its floor: not the table


def test_a_ball_with_nothing_under_it_reaches_down_to_the_table():
    seen = Box3D(np.r_[0.3, 0.3, TABLE + 0.03], np.r_[0.37, 0.37, TABLE + 0.07])  # its lower half out of sight
    plate = Instance3D(
        "plate", np.zeros((0, 3)), np.zeros((0, 3)), Box3D(np.r_[-0.1, -0.1, TABLE], np.r_[0.1, 0.1, 0.82]), (0,)
    )
    ball = Instance3D("orange", np.zeros((0, 3)), np.zeros((0, 3)), seen, (0,))
    assert ground([plate, ball], TABLE)[1].box.lower[2] == TABLE


def test_depth_pixels_put_an_object_on_what_they_show_under_it():
    box = _box_surface(np.array([0.0, 0.0, TABLE + 0.008]), np.array([0.08, 0.06, TABLE + 0.036]))
    assert object_box(box, TABLE).lower[2] == TABLE  # the fused surface's blur: taken to stand on the table
    assert object_box(box, TABLE, blur=0.004).lower[2] > TABLE + 0.007


def test_a_smaller_object_claims_the_points_in_its_box():
    cube = Instance3D(
        "rubiks cube", np.zeros((0, 3)), np.zeros((0, 3)), Box3D(np.r_[0, 0, TABLE], np.r_[0.06, 0.06, 0.86]), (0,)
    )
    points = np.array([[0.03, 0.03, 0.85], [0.063, 0.03, 0.85], [0.08, 0.03, 0.85], [np.nan, np.nan, np.nan]])
    assert _claimed_by([cube], points).tolist() == [True, True, False, False]
