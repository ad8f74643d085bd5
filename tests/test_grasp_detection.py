"""The antipodal grasp detector and the placement search, on point clouds and boxes built in the test."""

import math

import numpy as np

from roboscript.api.placement import fits, spot_at, spots_in_receptacle
from roboscript.geometry import Box3D, Transform
from roboscript.perception.base import ObjectPoints, Receptacle
from roboscript.perception.grasp_detection import GraspPreferences, GripperGeometry, detect_grasps


def box_surface(center, half, spacing=0.004, skip_bottom=True):
    """Points and outward normals on a box's faces (the bottom face is hidden on a table)."""
    points, normals = [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            if skip_bottom and axis == 2 and sign < 0:
                continue
            u, v = [a for a in range(3) if a != axis]
            for a in np.arange(-half[u], half[u] + 1e-9, spacing):
                for b in np.arange(-half[v], half[v] + 1e-9, spacing):
                    p = np.zeros(3)
                    p[axis], p[u], p[v] = sign * half[axis], a, b
                    n = np.zeros(3)
                    n[axis] = sign
                    points.append(center + p)
                    normals.append(n)
    return np.array(points), np.array(normals)


def table(z=0.82, extent=0.3, spacing=0.01):
    xs = np.arange(-extent, extent, spacing)
    grid = np.array([[x, y, z] for x in xs for y in xs])
    return grid


def test_antipodal_grasps_close_across_the_narrow_side_of_a_box():
    center = np.array([0.0, 0.0, 0.82 + 0.025])
    half = np.array([0.06, 0.02, 0.025])  # 12 x 4 x 5 cm
    points, normals = box_surface(center, half)
    scene = np.vstack([points, table()])
    grasps = detect_grasps(ObjectPoints(points, normals), scene, GripperGeometry(0.08), seed=1)
    assert grasps, "a 4 cm wide box must be graspable"
    best = grasps[0]
    closing, approach = best.pose.rotation[:, 1], best.pose.rotation[:, 2]
    assert abs(closing[1]) > 0.95  # across the 4 cm side
    assert approach[2] < -0.9  # from above, by default
    assert abs(best.width - 0.04) < 0.006
    assert best.pose.position[2] > 0.82 + 0.01  # the fingers stay above the table


def test_preferences_steer_the_ranking_and_too_wide_objects_get_nothing():
    center = np.array([0.0, 0.0, 0.82 + 0.03])
    points, normals = box_surface(center, np.array([0.02, 0.02, 0.03]))
    scene = np.vstack([points, table()])
    cloud = ObjectPoints(points, normals)
    side = detect_grasps(cloud, scene, GripperGeometry(0.08), GraspPreferences(approach=np.array([1.0, 0, 0])))
    assert side[0].pose.rotation[:, 2][0] > 0.9
    wide_points, wide_normals = box_surface(center, np.array([0.06, 0.06, 0.03]))
    assert detect_grasps(ObjectPoints(wide_points, wide_normals), scene, GripperGeometry(0.08)) == []


def test_placement_spots_avoid_occupants_and_fill_from_the_corner():
    receptacle = Receptacle("tray", Transform.identity(), np.array([-0.1, -0.1, 0.8]), np.array([0.1, 0.1, 0.9]))
    occupant = Box3D(np.array([-0.1, -0.1, 0.8]), np.array([0.0, 0.0, 0.85]))
    spots = spots_in_receptacle(receptacle, np.array([0.03, 0.03]), 0.0, 0.05, [occupant], np.array([-1.0, -1.0]))
    assert spots
    for spot in spots:
        assert not (spot.center[0] - 0.03 < 0.0 and spot.center[1] - 0.03 < 0.0)
    # The best spot hugs a wall near the requested corner (not the middle of the free area).
    assert min(spots[0].center[0], spots[0].center[1]) < -0.05
    assert fits(receptacle, np.array([0.09, 0.02]))
    assert not fits(receptacle, np.array([0.12, 0.02]))
    full = Box3D(np.array([-0.1, -0.1, 0.8]), np.array([0.1, 0.1, 0.85]))
    assert spots_in_receptacle(receptacle, np.array([0.03, 0.03]), 0.0, 0.05, [full], np.array([0.0, 0.0])) == []


def test_spot_at_never_sinks_below_the_support():
    spot = spot_at(np.array([0.1, 0.2, 0.5]), np.array([0.05, 0.05, 0.08]), support_top=0.82)
    assert math.isclose(spot.center[2], 0.82 + 0.04 + 0.012)
    high = spot_at(np.array([0.1, 0.2, 1.0]), np.array([0.05, 0.05, 0.08]), support_top=0.82)
    assert high.center[2] == 1.0
