"""The rules that turn an object's points into its own: the skirt of a support beside it, what a smaller object
claims, what an object rests on. Synthetic points, so that each rule is seen alone."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.geometry import Box3D
from roboscript.perception.reconstruction.instances import Instance3D, ground, object_box
from roboscript.perception.reconstruction.refinement import _claimed_by, without_skirt

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
    # The strip of the plate that the box's boxes in the images take in, on one side (the plate's rim went on).
    plate = _grid((-0.08, -0.05), (-0.035, 0.035), floor)
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


def _instance(label: str, box: Box3D, points: np.ndarray | None = None) -> Instance3D:
    points = np.zeros((0, 3)) if points is None else points
    normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))  # every point faces up: floors and tops
    return Instance3D(label, points, normals, box, (0,))


def test_a_box_on_a_plate_stands_on_the_plate_floor_seen_beside_it():
    floor = TABLE + 0.006
    plate_points = _grid((-0.1, 0.1), (-0.1, 0.1), floor)
    plate_points = plate_points[(np.abs(plate_points[:, 0]) > 0.045) | (np.abs(plate_points[:, 1]) > 0.035)]
    plate = _instance("plate", Box3D(np.r_[-0.1, -0.1, TABLE], np.r_[0.1, 0.1, TABLE + 0.02]), plate_points)
    lying = Box3D(np.r_[-0.04, -0.03, floor + 0.003], np.r_[0.04, 0.03, floor + 0.031])  # its foot seen 3 mm up
    grounded = ground([plate, _instance("gelatin box", lying)], TABLE)
    assert grounded[1].box.lower[2] == pytest.approx(floor)  # on the plate's floor, below its rim: not the table


def test_an_apple_in_a_bowl_reaches_down_to_the_bowl_bottom():
    bottom = TABLE + 0.01
    bowl_floor = _grid((-0.06, 0.06), (-0.06, 0.06), bottom)
    bowl = _instance("bowl", Box3D(np.r_[-0.09, -0.09, TABLE], np.r_[0.09, 0.09, TABLE + 0.07]), bowl_floor)
    seen = Box3D(np.r_[-0.035, -0.035, TABLE + 0.05], np.r_[0.035, 0.035, TABLE + 0.085])  # over the rim only
    assert ground([bowl, _instance("apple", seen)], TABLE)[1].box.lower[2] == pytest.approx(bottom)


def test_a_ball_with_nothing_under_it_reaches_down_to_the_table():
    seen = Box3D(np.r_[0.3, 0.3, TABLE + 0.03], np.r_[0.37, 0.37, TABLE + 0.07])  # its lower half out of sight
    beside = Box3D(np.r_[0.2, 0.2, TABLE], np.r_[0.4, 0.4, TABLE + 0.13])  # a turned basket's upright box
    wall = _grid((0.2, 0.25), (0.2, 0.4), TABLE + 0.13)  # its rim, over the ball's foot
    ball = _instance("orange", seen)
    assert ground([_instance("basket", beside, wall), ball], TABLE)[1].box.lower[2] == TABLE


def test_depth_pixels_put_an_object_on_what_they_show_under_it():
    box = _box_surface(np.array([0.0, 0.0, TABLE + 0.008]), np.array([0.08, 0.06, TABLE + 0.036]))
    assert object_box(box, TABLE).lower[2] == TABLE  # the fused surface's blur: taken to stand on the table
    assert object_box(box, TABLE, blur=0.004).lower[2] > TABLE + 0.007


def test_a_smaller_object_claims_the_points_on_its_surface():
    cube_points = _box_surface(np.r_[0.0, 0.0, TABLE], np.r_[0.06, 0.06, TABLE + 0.06])
    cube = _instance("rubiks cube", Box3D(np.r_[0, 0, TABLE], np.r_[0.06, 0.06, TABLE + 0.06]), cube_points)
    points = np.array([[0.03, 0.03, TABLE + 0.061], [0.063, 0.03, 0.85], [0.08, 0.03, 0.85], [np.nan] * 3])
    assert _claimed_by([cube], points).tolist() == [True, True, False, False]


def _one_view(size: int = 120) -> tuple[np.ndarray, np.ndarray]:
    """A view from above of a tray 0.3 m across (pixel i, j at 2.5 mm steps), 3 cm high, with a 5 cm cube on it
    at pixels 40..60 standing 1 cm over it (one piece with it, seen from above): its point and normal maps."""
    j, i = np.meshgrid(np.arange(size), np.arange(size))
    z = np.full(i.shape, TABLE + 0.03)
    cube = (i >= 40) & (i < 60) & (j >= 40) & (j < 60)
    z[cube] = TABLE + 0.04
    points = np.stack([j * 0.0025, i * 0.0025, z], axis=-1)
    return points, np.broadcast_to(np.array([0.0, 0.0, 1.0]), points.shape).copy()


def test_the_larger_object_gives_up_the_smaller_ones_surface_and_furniture_keeps_its_own():
    from roboscript.perception.detection.grounding import Detection2D
    from roboscript.perception.points import MapSurface
    from roboscript.perception.reconstruction.refinement import refine_all

    points, normals = _one_view()
    detections = [[Detection2D("tray", (0, 0, 120, 120)), Detection2D("cube", (36, 36, 64, 64))]]
    tray_box = Box3D(np.r_[0.0, 0.0, TABLE], np.r_[0.3, 0.3, TABLE + 0.06])  # the fused box: the cube's top in it
    cube_box = Box3D(np.r_[0.1, 0.1, TABLE], np.r_[0.15, 0.15, TABLE + 0.06])
    instances = [Instance3D("tray", np.zeros((0, 3)), np.zeros((0, 3)), tray_box, (0,))]
    instances.append(Instance3D("cube", np.zeros((0, 3)), np.zeros((0, 3)), cube_box, (1,)))

    tray, cube = refine_all(instances, detections, [MapSurface(points, normals)], TABLE)
    assert tray.points[:, 2].max() < TABLE + 0.035  # the cube's top is the cube's
    assert cube.points[:, 2].max() > TABLE + 0.035
    assert tray.box.upper[2] == pytest.approx(TABLE + 0.03, abs=0.002)

    tray, _ = refine_all(instances, detections, [MapSurface(points, normals)], TABLE, furniture={"tray"})
    assert tray.points[:, 2].max() > TABLE + 0.035  # a piece of furniture gives nothing up


def test_a_block_hiding_the_top_it_stands_on_is_not_taken_down_to_the_table():
    below = _instance("red box", Box3D(np.r_[0.0, 0.0, TABLE], np.r_[0.06, 0.06, TABLE + 0.05]))
    block = _instance("green block", Box3D(np.r_[0.0, 0.0, TABLE + 0.052], np.r_[0.06, 0.06, TABLE + 0.1]))
    assert ground([below, block], TABLE)[1].box.lower[2] == pytest.approx(TABLE + 0.052)


def test_a_block_on_a_box_stands_on_the_ring_of_its_top_seen_round_it_not_on_stray_points_at_its_foot():
    top = TABLE + 0.05
    ring = _grid((-0.04, 0.04), (-0.04, 0.04), top)
    ring = ring[(np.abs(ring[:, 0]) > 0.03) | (np.abs(ring[:, 1]) > 0.03)][:8]  # the block hides all but a sliver
    stray = np.array([[0.041, 0.0, TABLE + 0.004], [0.0, 0.041, TABLE + 0.005]])  # the table at the box's foot
    below = _instance("red box", Box3D(np.r_[-0.04, -0.04, TABLE], np.r_[0.04, 0.04, top]), np.vstack([ring, stray]))
    block = _instance("green block", Box3D(np.r_[-0.03, -0.03, top + 0.001], np.r_[0.03, 0.03, top + 0.05]))
    assert ground([below, block], TABLE)[1].box.lower[2] == pytest.approx(top, abs=0.002)


def test_a_few_points_of_the_boxs_side_kept_as_the_blocks_do_not_take_it_down_to_the_table():
    # The block's 2D boxes hold a little of the box's side under it: three points 1.6 cm under the box's top.
    top = TABLE + 0.05
    below = _instance("red box", Box3D(np.r_[-0.04, -0.04, TABLE], np.r_[0.04, 0.04, top]))
    block = _box_surface(np.r_[-0.03, -0.03, top], np.r_[0.03, 0.03, top + 0.05], step=0.01)  # as few as seen
    strays = np.array([[-0.03, 0.0, top - 0.016], [-0.029, 0.01, top - 0.012], [-0.03, 0.02, top - 0.011]])
    points = np.vstack([block, strays])
    seen = Instance3D("green block", points, np.zeros_like(points), object_box(points, TABLE), (0,))
    assert ground([below, seen], TABLE)[1].box.lower[2] > top - 0.02


def test_objects_are_refined_smallest_in_space_first_however_small_the_images_show_them():
    from roboscript.perception.detection.grounding import Detection2D
    from roboscript.perception.points import MapSurface
    from roboscript.perception.reconstruction.refinement import refine_all

    points, normals = _one_view()
    # The tray's box in the image is the smaller (as a box under a block is, hidden by it from above).
    detections = [[Detection2D("tray", (30, 30, 70, 70)), Detection2D("cube", (29, 29, 71, 71))]]
    tray_box = Box3D(np.r_[0.0, 0.0, TABLE], np.r_[0.3, 0.3, TABLE + 0.06])
    cube_box = Box3D(np.r_[0.1, 0.1, TABLE], np.r_[0.15, 0.15, TABLE + 0.06])
    instances = [Instance3D("tray", np.zeros((0, 3)), np.zeros((0, 3)), tray_box, (0,))]
    instances.append(Instance3D("cube", np.zeros((0, 3)), np.zeros((0, 3)), cube_box, (1,)))
    tray, cube = refine_all(instances, detections, [MapSurface(points, normals)], TABLE)
    assert tray.points[:, 2].max() < TABLE + 0.035 and cube.points[:, 2].max() > TABLE + 0.035


def test_an_apple_by_a_bowls_wall_stands_on_its_bottom_not_on_the_rim_seen_beside_it():
    bottom, rim = TABLE + 0.01, TABLE + 0.06
    floor = _grid((0.0, 0.02), (-0.03, 0.03), bottom)  # a sliver of the bottom shows beside the apple
    lip = _grid((-0.06, -0.05), (-0.04, 0.04), rim, step=0.002)  # the rim's top, many points, as close
    bowl = _instance("bowl", Box3D(np.r_[-0.09, -0.09, TABLE], np.r_[0.09, 0.09, rim]), np.vstack([floor, lip]))
    seen = Box3D(np.r_[-0.045, -0.035, rim + 0.005], np.r_[0.0, 0.035, rim + 0.04])  # over the rim only
    assert ground([bowl, _instance("apple", seen)], TABLE)[1].box.lower[2] == pytest.approx(bottom, abs=0.002)
