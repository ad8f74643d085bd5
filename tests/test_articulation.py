"""Articulation from points: drawer axes and a door's hinge estimated from the camera points of the cabinet's
fronts (selected by the simulator's segmentation, as the 3D instance step would select them), against the
simulator's joints."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.assembly import build_perception
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.base import ArticulationJoint
from roboscript.perception.furniture.articulation import door_joint, drawer_joint, front_plane, moved_with_handle
from roboscript.perception.points import entity_points


@pytest.fixture(scope="module")
def cabinet():
    backend = MujocoBackend("cluttered_5_mug_to_cabinet", robot="panda")
    frames = [backend.capture(c) for c in backend.camera_names()]
    truth = build_perception(backend, "gt")
    yield backend, frames, truth
    backend.close()


def _front(backend, frames, part: str) -> np.ndarray:
    points, _ = entity_points(frames, backend.ground_truth.world.entity(part).index)
    return points


@pytest.mark.parametrize("index", [0, 1, 2])
def test_a_drawer_slides_along_its_fronts_normal(cabinet, index):
    backend, frames, truth = cabinet
    handle = f"cabinet.handle_{index}"
    (expected,) = truth.joints(handle)
    found = drawer_joint(expected.part, _front(backend, frames, expected.part), truth.box(handle).center)
    assert found.type == "prismatic" and found.part == expected.part
    assert np.degrees(np.arccos(np.clip(found.axis @ expected.axis, -1, 1))) < 3.0
    assert np.linalg.norm(found.position - expected.position) < 0.01


def test_a_door_turns_about_the_edge_away_from_its_handle(cabinet):
    backend, frames, truth = cabinet
    (expected,) = truth.joints("cabinet.handle_3")
    found = door_joint(expected.part, _front(backend, frames, expected.part), truth.box("cabinet.handle_3").center)
    assert found.type == "revolute"
    assert np.allclose(found.axis, expected.axis)  # positive angles open, as in the simulator
    # The same vertical line: compare where each crosses the handle's height.
    assert np.linalg.norm(found.position[:2] - expected.position[:2]) < 0.02


def test_too_few_points_for_a_front_is_an_error():
    with pytest.raises(ValueError, match="at least 10 points, got 3"):
        front_plane(np.zeros((3, 3)), np.ones(3))


def test_the_camera_pipeline_estimates_every_cabinet_joint(cabinet):
    """With ground-truth 2D boxes (no segmentation masks), fronts and handles are cut from the fused views as any
    object is, and the joints estimated from them."""
    backend, _, truth = cabinet
    seen = build_perception(backend, "gt-2d")
    expected, found = truth.joints("cabinet"), seen.joints("cabinet")
    assert [j.part for j in found] == [j.part for j in expected] and len(found) == 4
    for e, f in zip(expected, found, strict=True):
        assert f.type == e.type
        assert np.degrees(np.arccos(np.clip(f.axis @ e.axis, -1, 1))) < 1.0  # same direction, same sign
        offset = f.position - e.position
        assert np.linalg.norm(offset - (offset @ e.axis) * e.axis) < 0.01  # the same line
    assert seen.joints("cabinet.handle_1")[0].part == "cabinet.drawer_1"


def test_a_part_no_view_saw_cannot_have_its_joint_estimated(cabinet):
    """Asked of the part, it says so; asked of the whole cabinet, the parts seen answer (a drawer pulled out hides
    the front of the one below it, which should not keep a program from the one it means)."""
    backend, _, _ = cabinet
    seen = build_perception(backend, "gt-2d")
    seen.detect(["mug"])
    del seen.furniture_seen.seen["cabinet.drawer_2"]
    with pytest.raises(KeyError, match=r"'cabinet.drawer_2' was not found"):
        seen.joints("cabinet.drawer_2")
    parts = {j.part for j in seen.joints("cabinet")}
    assert "cabinet.drawer_2" not in parts and {"cabinet.drawer_0", "cabinet.drawer_1"} <= parts


def test_an_open_drawers_axis_is_still_its_fronts_normal():
    """Open, a drawer shows the cameras above it more bottom than front: the front is the upright plane."""
    backend = MujocoBackend("cluttered_5_mug_to_cabinet", robot="panda")
    try:
        truth = build_perception(backend, "gt")
        (closed,) = truth.joints("cabinet.drawer_1")
        world = backend.sim_world
        body = world.entity("cabinet.drawer_1").bodies[0]
        world.data.qpos[world.model.jnt_qposadr[world.model.body_jntadr[body]]] = 0.2  # pulled out 20 cm
        backend.wait(0.2)
        assert truth.joints("cabinet.drawer_1")[0].value > 0.15
        seen = build_perception(backend, "gt-2d")
        (found,) = seen.joints("cabinet.drawer_1")
        assert np.degrees(np.arccos(np.clip(found.axis @ closed.axis, -1, 1))) < 2.0
    finally:
        backend.close()


def test_furniture_parts_are_measured_from_their_points(cabinet):
    """With ground-truth 2D boxes, the handles' boxes (the points standing out of their fronts) against the
    simulator's, the fronts' normals, and a part no camera saw, which is "not found" rather than answered."""
    backend, _, truth = cabinet
    seen = build_perception(backend, "gt-2d")
    seen.detect(["mug"])
    for handle in ("cabinet.handle_0", "cabinet.handle_1", "cabinet.handle_2", "cabinet.handle_3"):
        assert np.linalg.norm(seen.box(handle).center - truth.box(handle).center) < 0.006, handle
    for drawer in ("cabinet.drawer_0", "cabinet.drawer_1", "cabinet.drawer_2"):
        on_front = truth.box(drawer.replace("drawer", "handle")).center - np.array(
            [0.02, 0.14, 0.0]
        )  # clear of the handle
        normal = seen.plane_normal(drawer, on_front)
        assert normal @ truth.plane_normal(drawer, on_front) > np.cos(np.radians(2.0)), (drawer, normal)
    assert seen.receptacle("cabinet.handle_1") is None and seen.receptacle("cabinet") is None
    del seen.furniture_seen.seen["cabinet.handle_3"]
    assert "cabinet.handle_3" not in seen.names()
    with pytest.raises(KeyError, match=r"'cabinet.handle_3' was not found: no camera has seen it"):
        seen.require("cabinet.handle_3")


def test_a_front_and_a_handle_from_different_looks_give_no_joint(cabinet):
    """A handle last seen in an earlier look may have moved with its drawer since: the joint is estimated only
    from a front and a handle one look saw together; it does not look again by itself (it is asked for every part
    near the gripper)."""
    backend, _, _ = cabinet
    seen = build_perception(backend, "gt-2d")
    seen.detect(["mug"])
    seen.detect(["mug"])
    seen.furniture_seen.look_of["cabinet.handle_1"] = seen.looks - 1
    with pytest.raises(
        KeyError, match=r"'cabinet.drawer_1' was not found: its front and its handle .* different looks"
    ):
        seen.joints("cabinet.drawer_1")
    assert seen.joints("cabinet.drawer_0")[0].part == "cabinet.drawer_0"


def test_a_front_is_fitted_to_points_that_face_its_way():
    """A pulled drawer seen with the arm at its handle: a few points of its front, many of its bottom. A vertical
    plane cutting through the bottom holds more points than the front does, but none of them faces its way."""
    rng = np.random.default_rng(0)
    front = np.column_stack([np.zeros(60), rng.uniform(-0.15, 0.15, 60), rng.uniform(-0.06, 0.06, 60)])
    bottom = np.column_stack([rng.uniform(-0.3, 0.0, 4000), rng.uniform(-0.17, 0.17, 4000), np.full(4000, -0.06)])
    points = np.vstack([front, bottom])
    normals = np.vstack([np.tile([1.0, 0, 0], (60, 1)), np.tile([0, 0, 1.0], (4000, 1))])
    handle = np.array([0.03, 0.0, 0.0])
    _, normal, on_plane = front_plane(points, handle, normals=normals)
    assert abs(normal[0]) > 0.99 and len(on_plane) == 60


def test_a_front_plane_keeps_the_plane_one_hypothesis_at_a_time_would_keep():
    """The hypotheses are tested all at once; the winner is what testing them in order finds: the first with the
    most inliers among the same draws."""
    from roboscript.perception.furniture import articulation as a

    def in_order(points, toward, normals, seed):
        rng = np.random.default_rng(seed)
        best = np.zeros(len(points), dtype=bool)
        upright = np.flatnonzero(np.abs(np.nan_to_num(normals[:, 2], nan=1.0)) < a.MAX_TILT)
        for _ in range(200):
            p, q, r = points[rng.choice(upright, 3, replace=False)]
            normal = np.cross(q - p, r - p)
            if np.linalg.norm(normal) < 1e-9:
                continue
            normal /= np.linalg.norm(normal)
            if abs(normal[2]) > a.MAX_TILT or abs(np.dot(toward - p, normal)) > a.HANDLE_REACH:
                continue
            inliers = (np.abs((points - p) @ normal) < a.PLANE_TOLERANCE) & (np.abs(normals @ normal) > a.FACING)
            if inliers.sum() > best.sum():
                best = inliers
        return points[best]

    rng = np.random.default_rng(1)
    for seed in range(6):
        n = int(rng.integers(100, 3000))
        front = np.column_stack([rng.uniform(-0.2, 0.2, n), 0.4 + rng.normal(0, 0.002, n), rng.uniform(0.9, 1.1, n)])
        floor = np.column_stack([rng.uniform(-0.2, 0.2, n), rng.uniform(0.2, 0.4, n), np.full(n, 0.9)])
        points = np.vstack([front, floor])
        normals = np.vstack([np.tile([0, -1.0, 0], (n, 1)), np.tile([0, 0, 1.0], (n, 1))])
        normals += rng.normal(0, 0.3, normals.shape)  # noisy enough that the facing test decides for some points
        toward = np.array([0.0, 0.37, 1.0])
        _, _, on_plane = front_plane(points, toward, seed=seed, normals=normals)
        assert np.array_equal(on_plane, in_order(points, toward, normals, seed))


def test_a_drawer_joint_moves_with_its_handle_and_a_hinge_stays():
    drawer = ArticulationJoint("cabinet.drawer_1", "prismatic", np.array([-0.2, 0.6, 1.2]), np.array([1.0, 0, 0]),
                               0.0, 0.0, 0.3)  # fmt: skip
    moved = moved_with_handle(drawer, np.array([-0.17, 0.6, 1.2]), np.array([0.05, 0.62, 1.19]))
    assert np.allclose(moved.position, [0.02, 0.6, 1.2]) and np.allclose(moved.axis, drawer.axis)
    door = ArticulationJoint("cabinet.door_0", "revolute", np.array([-0.2, 0.4, 1.0]), np.array([0, 0, 1.0]),
                             0.0, 0.0, 1.5)  # fmt: skip
    assert moved_with_handle(door, np.zeros(3), np.ones(3)) is door
