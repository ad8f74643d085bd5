"""The antipodal grasp detector and the placement search, on point clouds and boxes built in the test."""

import math

import numpy as np
import pytest

from roboscript.api.spots import Footprint, fits, gap, spots_in_receptacle
from roboscript.geometry import Box3D, Transform
from roboscript.grasping.detection import (
    GraspPreferences,
    GripperGeometry,
    _gripper_reach,
    collides,
    detect_grasps,
    falls_free,
    object_middle,
    pad_contact,
)
from roboscript.perception.base import ObjectPoints, Receptacle


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


def test_the_hand_is_as_wide_as_the_hand_and_the_fingers_sweep_from_open():
    """A point 9 cm along the closing direction and 4 cm back from the TCP is inside the Franka hand (a mug's far
    rim under the hand); a point 5 cm out, beside the tips, is where an open finger comes down before closing."""
    gripper = GripperGeometry(max_width=0.08)
    upright = np.eye(3)
    beside_the_hand = np.array([[0.0, 0.09, -0.04]])
    assert collides(upright, np.zeros(3), beside_the_hand, gripper, width=0.02)
    beside_the_tips = np.array([[0.0, 0.045, -0.01]])
    assert collides(upright, np.zeros(3), beside_the_tips, gripper, width=0.02)
    clear = np.array([[0.0, 0.09, 0.02], [0.0, 0.0, 0.03], [0.05, 0.0, -0.02]])  # past the tips; in front; aside
    assert not collides(upright, np.zeros(3), clear, gripper, width=0.02)


def test_placement_spots_avoid_occupants_and_fill_from_the_corner():
    receptacle = Receptacle("tray", Transform.identity(), np.array([-0.1, -0.1, 0.8]), np.array([0.1, 0.1, 0.9]))
    occupant = Footprint.of_box(Box3D(np.array([-0.1, -0.1, 0.8]), np.array([0.0, 0.0, 0.85])))
    spots = spots_in_receptacle(receptacle, np.array([0.03, 0.03]), 0.0, 0.05, [occupant], np.array([-1.0, -1.0]))
    assert spots
    for spot in spots:
        assert not (spot.center[0] - 0.03 < 0.0 and spot.center[1] - 0.03 < 0.0)
    # The best spot hugs a wall near the requested corner (not the middle of the free area).
    assert min(spots[0].center[0], spots[0].center[1]) < -0.05
    assert fits(receptacle, np.array([0.09, 0.02]))
    assert not fits(receptacle, np.array([0.12, 0.02]))
    full = Footprint.of_box(Box3D(np.array([-0.1, -0.1, 0.8]), np.array([0.1, 0.1, 0.85])))
    assert spots_in_receptacle(receptacle, np.array([0.03, 0.03]), 0.0, 0.05, [full], np.array([0.0, 0.0])) == []


def test_a_turned_occupant_blocks_only_the_strip_it_covers():
    """A banana lying across a plate at 45 degrees: its world-aligned box would cover nearly all of a 20 cm plate,
    its turned footprint leaves room beside it in two corners."""
    plate = Receptacle("plate", Transform.identity(), np.array([-0.1, -0.1, 0.8]), np.array([0.1, 0.1, 0.9]))
    banana = Footprint(np.zeros(2), math.pi / 4, np.array([0.1, 0.025]))
    spots = spots_in_receptacle(plate, np.array([0.025, 0.025]), 0.0, 0.05, [banana], np.array([-1.0, 1.0]))
    assert spots and all(gap(Footprint(s.center[:2], 0.0, np.array([0.025, 0.025])), banana) >= 0 for s in spots)
    as_a_box = Footprint.of_box(Box3D(np.array([-0.08, -0.08, 0.8]), np.array([0.08, 0.08, 0.85])))
    assert spots_in_receptacle(plate, np.array([0.025, 0.025]), 0.0, 0.05, [as_a_box], np.array([-1.0, 1.0])) == []
    assert gap(Footprint(np.array([0.3, 0.0]), 0.0, np.array([0.1, 0.1])), banana) > 0.1


def test_each_robots_hand_box_holds_its_hand():
    """The hand boxes in the robot descriptions against the models: every vertex of the gripper's collision
    meshes that are not fingers lies within the box (fully open, in the TCP frame), and the box is no more than
    2 mm larger than they are."""
    import mujoco

    from roboscript.backends.mujoco_backend import MujocoBackend

    fingers = {"panda": ("left_finger", "right_finger"), "ur5e": ("follower", "pad")}
    for robot in ("panda", "ur5e"):
        backend = MujocoBackend("world_2_pick_and_place", robot=robot)
        try:
            model, data = backend.sim_world.model, backend.sim_world.data
            tcp = backend.tcp_pose()
            hand = int(model.site(backend.robot.qualified(backend.robot.tcp_site)).bodyid[0])
            lower, upper = (np.array(c) for c in backend.robot.gripper.hand_box)
            checked, seen_lower, seen_upper = 0, np.full(3, np.inf), np.full(3, -np.inf)
            for g in range(model.ngeom):
                body = int(model.geom_bodyid[g])
                if not _descends(model, body, hand) or any(f in model.body(body).name for f in fingers[robot]):
                    continue
                if model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 0:
                    continue
                assert model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH, model.body(body).name
                mesh = model.geom_dataid[g]
                start = model.mesh_vertadr[mesh]
                vertices = model.mesh_vert[start : start + model.mesh_vertnum[mesh]]
                local = tcp.inverse().apply(data.geom_xpos[g] + vertices @ data.geom_xmat[g].reshape(3, 3).T)
                assert np.all(local >= lower) and np.all(local <= upper), (robot, model.body(body).name)
                seen_lower, seen_upper = (
                    np.minimum(seen_lower, local.min(axis=0)),
                    np.maximum(seen_upper, local.max(axis=0)),
                )
                checked += 1
            assert np.all(seen_lower - lower < 0.002) and np.all(upper - seen_upper < 0.002), (
                robot,
                seen_lower,
                seen_upper,
            )
            assert checked >= (1 if robot == "panda" else 7), (robot, checked)
        finally:
            backend.close()


def _descends(model, body: int, root: int) -> bool:
    while body > 0:
        if body == root:
            return True
        body = int(model.body_parentid[body])
    return False


def sphere_surface(center, radius, n=1500):
    """Points and outward normals on the upper part of a sphere (what cameras above a table see)."""
    k = np.arange(n) + 0.5
    polar, azimuth = np.arccos(1 - 2 * k / n), math.pi * (1 + 5**0.5) * k
    normals = np.column_stack([np.sin(polar) * np.cos(azimuth), np.sin(polar) * np.sin(azimuth), np.cos(polar)])
    normals = normals[normals[:, 2] > -0.5]
    return center + radius * normals, normals


def test_objects_nearly_as_wide_as_the_opening_are_graspable_and_wider_ones_are_not():
    # 2 mm to spare on each side of the Panda's 8 cm is enough for a parallel gripper: a 7.6 cm box (the apple's
    # width) closes across its narrow side; a 7.9 cm one gets nothing.
    for across, graspable in ((0.076, True), (0.079, False)):
        center = np.array([0.0, 0.0, 0.82 + 0.02])
        points, normals = box_surface(center, np.array([across / 2, 0.05, 0.02]))
        scene = np.vstack([points, table()])
        grasps = detect_grasps(ObjectPoints(points, normals), scene, GripperGeometry(0.08), seed=1)
        assert bool(grasps) is graspable, across
        if grasps:
            assert abs(grasps[0].width - across) < 0.004 and abs(grasps[0].pose.rotation[0, 1]) > 0.95


def test_a_ball_is_gripped_at_its_equator_where_the_palm_clears_its_top():
    # The Franka's palm is 3.6 cm behind the fingertips: a 7 cm ball fits under it, a 7.6 cm one (the apple)
    # does not, and is left to the central lift grasp the adaptive tool falls back on.
    for diameter, graspable in ((0.070, True), (0.076, False)):
        center = np.array([0.0, 0.0, 0.82 + diameter / 2])
        points, normals = sphere_surface(center, diameter / 2)
        grasps = detect_grasps(ObjectPoints(points, normals), np.vstack([points, table()]), GripperGeometry(0.08))
        assert bool(grasps) is graspable, diameter


def test_the_open_fingers_must_clear_what_stands_just_beyond_a_full_width_grasp():
    # A 7.4 cm wide box with a post 4 mm off one side (a cup's handle): across the box, the open finger (its inner
    # face 3 mm outside the box) comes down on the post.
    center = np.array([0.0, 0.0, 0.82 + 0.03])
    points, _ = box_surface(center, np.array([0.037, 0.025, 0.03]))
    post = np.array([[0.041, y, z] for y in np.linspace(-0.008, 0.008, 5) for z in np.linspace(0.83, 0.87, 9)])
    scene = np.vstack([points, post, table()])
    rotation = np.column_stack([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])  # closing along x
    assert collides(rotation, center, scene, GripperGeometry(0.08), width=0.074)
    assert not collides(rotation, center, np.vstack([points, table()]), GripperGeometry(0.08), width=0.074)


def flared_cup_surface(center_xy, bottom_radius, rim_radius, height, z0=0.82, n=60, rings=24):
    """Outer wall points and outward normals of a cup that widens upwards (no inside, no bottom)."""
    slope = (rim_radius - bottom_radius) / height
    points, normals = [], []
    for h in np.linspace(0.0, height, rings):
        r = bottom_radius + slope * h
        for a in np.linspace(0.0, 2 * math.pi, n, endpoint=False):
            points.append([center_xy[0] + r * math.cos(a), center_xy[1] + r * math.sin(a), z0 + h])
            normal = np.array([math.cos(a), math.sin(a), -slope])
            normals.append(normal / np.linalg.norm(normal))
    return np.array(points), np.array(normals)


def test_the_open_fingers_must_clear_a_flared_rim_they_pass_on_the_way_in():
    # A cup 7.6 cm across low down and 8.3 cm at the rim, in the 2F-85's 8.5 cm: a grasp across its body has room
    # where the pads close, but the fingers would pass the rim with 1 mm to spare, less than a point cloud's
    # error at an edge. A cup 7.4 cm at the rim leaves them 5.5 mm: gripped across.
    gripper = GripperGeometry(0.085)
    for rim, across in ((0.0415, False), (0.037, True)):
        points, normals = flared_cup_surface((0.0, 0.0), 0.034, rim, 0.09)
        grasps = detect_grasps(ObjectPoints(points, normals), np.vstack([points, table()]), gripper, seed=1)
        full_width = [g for g in grasps if g.width > 0.06]
        assert bool(full_width) is across, rim


def test_a_flared_cup_let_go_from_the_side_must_fall_free_of_the_open_fingers():
    # A cup 6 cm across at its foot and 8.8 cm at its rim, 9 cm tall, held from the side across its body in the
    # Panda's 8 cm: 5.3 cm up, it is 7.7 cm across, and falling 1.2 cm when let go brings 8.1 cm to the pads.
    # Held 2 cm up, the fingers' top edge 3 cm up, it falls free; so does a straight 7.4 cm cylinder, which
    # the way-in rule (2.5 mm) lets through too.
    gripper = GripperGeometry(0.08)
    flared, _ = flared_cup_surface((0.0, 0.0), 0.03, 0.044, 0.09)
    straight, _ = flared_cup_surface((0.0, 0.0), 0.037, 0.037, 0.09)
    side = np.column_stack([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])  # approach +x, closing along y
    high, low = np.array([0.0, 0.0, 0.82 + 0.053]), np.array([0.0, 0.0, 0.82 + 0.02])
    assert not falls_free(side, high, flared, gripper, drop=0.012)
    assert falls_free(side, high, flared, gripper, drop=0.0)
    assert falls_free(side, low, flared, gripper, drop=0.012)
    assert falls_free(side, high, straight, gripper, drop=0.012)


def test_the_middle_of_a_box_seen_from_one_side_is_the_middle_of_its_top():
    # A 9.5 x 6 x 5 cm box whose +x side alone is seen (the cameras stand on that side): that face's points pull
    # the median of all points towards it, the top face's do not.
    center = np.array([0.0, 0.0, 0.82 + 0.025])
    points, normals = box_surface(center, np.array([0.0475, 0.03, 0.025]))
    seen = (normals[:, 2] > 0.5) | (normals[:, 0] > 0.5)
    cloud = ObjectPoints(points[seen], normals[seen])
    assert abs(float(np.median(cloud.points[:, 0]))) > 0.01  # what the median of every point gives
    middle, _ = object_middle(cloud)
    assert np.linalg.norm(middle[:2] - center[:2]) < 0.003, middle


def test_no_point_beyond_the_gripper_reach_can_collide():
    # detect_grasps leaves out what is farther than this from a pair's middle: nothing there may ever count.
    for gripper in (GripperGeometry(0.08), GripperGeometry(0.085, hand_lower=(-0.04, -0.12, -0.15))):
        reach = _gripper_reach(gripper)
        points = np.random.default_rng(0).uniform(-2 * reach, 2 * reach, size=(400_000, 3))
        distance = np.linalg.norm(points, axis=1)
        for width in (0.0, 0.04, gripper.max_width - 0.003):
            assert not collides(np.eye(3), np.zeros(3), points[distance > reach], gripper, width)
            assert collides(np.eye(3), np.zeros(3), points[distance < reach], gripper, width)


def cylinder_surface(center_xy, radius, z_low, z_high, spacing=0.003):
    """Points and outward normals on a vertical cylinder's side and its top."""
    points, normals = [], []
    turns = max(int(2 * math.pi * radius / spacing), 8)
    for z in np.arange(z_low, z_high + 1e-9, spacing):
        for k in range(turns):
            a = 2 * math.pi * k / turns
            n = np.array([math.cos(a), math.sin(a), 0.0])
            points.append([center_xy[0] + radius * n[0], center_xy[1] + radius * n[1], z])
            normals.append(n)
    for r in np.arange(0.0, radius, spacing):
        for k in range(max(int(2 * math.pi * r / spacing), 1)):
            a = 2 * math.pi * k / max(int(2 * math.pi * r / spacing), 1)
            points.append([center_xy[0] + r * math.cos(a), center_xy[1] + r * math.sin(a), z_high])
            normals.append([0.0, 0.0, 1.0])
    return np.array(points), np.array(normals)


def test_only_what_lies_against_the_pads_counts_as_held():
    # A 4 cm bottle body up to 6 cm, a 2.4 cm neck above it: held at the shoulder, the pads touch the body's top
    # centimetre only; the neck between them is not held.
    body, _ = cylinder_surface((0.0, 0.0), 0.02, 0.82, 0.88)
    neck, _ = cylinder_surface((0.0, 0.0), 0.012, 0.88, 0.90)
    points = np.vstack([body, neck])
    down = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])  # approach -z, closing along -y
    at_shoulder = pad_contact(down, np.array([0.0, 0.0, 0.89]), points, 0.04)
    lower = pad_contact(down, np.array([0.0, 0.0, 0.86]), points, 0.04)
    assert at_shoulder < 0.012
    assert lower > 0.02
    # A box grasp closes from the full opening: the pads stop where the object is widest, and what lies there is
    # held all the same (counted against the opening's faces, a banana held across its middle counted as nothing).
    assert pad_contact(down, np.array([0.0, 0.0, 0.86]), points, 0.077) == pytest.approx(lower, abs=0.002)
