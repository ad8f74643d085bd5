"""What the layers above ask of a backend beyond motion and cameras: joint states by name, the base pose, a clock
to listen to, images for people, segmentation labels; and how the assembly treats a backend without ground truth."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.assembly import build_tools
from roboscript.backends.base import Backend, BackendError
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.planning.kinematics import ArmKinematics
from roboscript.robots import ROBOT_PREFIX


@pytest.fixture(scope="module", params=["panda", "ur5e"])
def backend(request):
    with MujocoBackend("world_2_pick_and_place", robot=request.param, settle=0.2) as b:
        yield b


def test_joint_states_name_every_arm_and_gripper_joint_as_the_robots_model_does(backend):
    states = backend.joint_states()
    arm = backend.robot.arm_joints
    # The robot model's own names (the UR5e's gripper is attached in it as gripper/...), as a driver reports them.
    assert not any(name.startswith(ROBOT_PREFIX) for name in states)
    assert set(arm) < set(states)  # the gripper's joints too
    assert np.allclose([states[j] for j in arm], backend.joint_positions())


def test_the_base_pose_is_where_the_kinematics_must_mount_the_arm(backend):
    kinematics = ArmKinematics(backend.robot, backend.base_pose())
    tcp = kinematics.fk(backend.joint_positions())
    assert np.linalg.norm(tcp.position - backend.tcp_pose().position) < 1e-6


def test_clock_listeners_hear_the_time_advance_until_removed(backend):
    heard: list[float] = []
    backend.add_clock_listener(heard.append)
    start = backend.time()
    backend.wait(0.05)
    backend.remove_clock_listener(heard.append)
    assert len(heard) > 5 and heard == sorted(heard) and start < heard[0] and heard[-1] <= backend.time() + 1e-9
    count = len(heard)
    backend.wait(0.02)
    assert len(heard) == count
    assert backend.simulator._callbacks == []  # no step callback left to cost every tick


def test_render_gives_any_model_camera_at_the_size_asked_and_names_the_cameras_otherwise(backend):
    assert backend.render("overview", 160, 120).shape == (120, 160, 3)
    with pytest.raises(BackendError, match=r"no camera named 'nope' to render; cameras: .*camera_left"):
        backend.render("nope", 160, 120)


def test_the_default_render_resizes_the_captured_frame(backend):
    frame = backend.capture("camera_left")
    small = Backend.render(backend, "camera_left", 64, 48)  # the interface's own, for backends without a renderer
    assert small.shape == (48, 64, 3)
    assert np.array_equal(small[0, 0], frame.rgb[0, 0])
    assert np.array_equal(small[47, 63], frame.rgb[47 * frame.rgb.shape[0] // 48, 63 * frame.rgb.shape[1] // 64])


def test_segmentation_labels_name_the_robot_and_the_objects(backend):
    labels = backend.segmentation_labels()
    frame = backend.capture("camera_left")
    robot = [i for i, name in labels.items() if name == "robot"]
    assert len(robot) == 1 and np.any(frame.segmentation == robot[0])
    assert {"apple", "footed_bowl"} <= set(labels.values())


class NoGroundTruthBackend(MujocoBackend):
    """A test double: a simulation that hides its ground truth, as a real robot has none."""

    @property
    def ground_truth(self):
        return None


def test_modes_that_take_ground_truth_are_refused_on_a_backend_without_it():
    with NoGroundTruthBackend("world_2_pick_and_place", settle=0) as backend:
        with pytest.raises(BackendError, match=r"perception gt-3d takes 3d from ground truth, which only a simulation"):
            build_tools(backend, perception="gt-3d")
        with pytest.raises(BackendError, match="perception gt takes 2d, 3d, scene from ground truth"):
            build_tools(backend)


def test_camera_perception_without_open3d_says_which_extra_to_install(monkeypatch):
    import importlib.util

    from roboscript.assembly import build_perception
    from roboscript.errors import MissingExtraError
    from roboscript.extras import install_hint

    real_find_spec = importlib.util.find_spec

    # Test double: Open3D looks absent, as on an install without the perception extra.
    def find_spec(name, *args):
        return None if name == "open3d" else real_find_spec(name, *args)

    monkeypatch.setattr(importlib.util, "find_spec", find_spec)
    with MujocoBackend("world_2_pick_and_place", settle=0) as backend:
        with pytest.raises(MissingExtraError, match=r"--perception gt-2d needs Open3D") as info:
            build_perception(backend, "gt-2d")
        assert install_hint("perception") in str(info.value)
        assert build_perception(backend, "gt").names()  # ground truth needs no Open3D


def test_a_capture_without_colour_has_the_same_depth_and_segmentation(backend):
    full = backend.capture("camera_right")
    plain = backend.capture("camera_right", color=False)
    assert plain.rgb is None and full.rgb is not None
    assert np.array_equal(plain.depth, full.depth) and np.array_equal(plain.segmentation, full.segmentation)
    assert np.allclose(plain.extrinsics.matrix(), full.extrinsics.matrix())


def test_a_capture_without_segmentation_has_the_same_colour_and_depth(backend):
    full = backend.capture("camera_left")
    plain = backend.capture("camera_left", segmentation=False)
    assert plain.segmentation is None and full.segmentation is not None
    assert np.array_equal(plain.depth, full.depth) and np.array_equal(plain.rgb, full.rgb)


def _mujocos_own_depth_and_segmentation(world, camera: str) -> tuple[np.ndarray, np.ndarray]:
    """What mujoco.Renderer's depth and segmentation modes give, a pass each, in the Renderer's conventions
    (metres, 0 where nothing was hit; entity indices, -1 where none): the reference for the single pass."""
    import mujoco

    with mujoco.Renderer(world.model, height=480, width=640) as renderer:
        renderer.update_scene(world.data, camera=camera)
        renderer.enable_depth_rendering()
        depth = renderer.render().astype(np.float32)
        renderer.disable_depth_rendering()
        renderer.enable_segmentation_rendering()
        ids, types = np.moveaxis(renderer.render(), -1, 0)
    depth[depth >= world.model.vis.map.zfar * world.model.stat.extent * 0.999] = 0.0
    entities = np.full(ids.shape, -1, dtype=np.int32)
    is_geom = (types == int(mujoco.mjtObj.mjOBJ_GEOM)) & (ids >= 0)
    entities[is_geom] = np.asarray(world.geom_entity)[ids[is_geom]]
    return depth, entities


def test_depth_and_segmentation_from_one_pass_equal_mujocos_own_passes_with_or_without_antialiasing(backend):
    from roboscript.sim.cameras import Renderer

    data, world = backend.sim_world.data, backend.sim_world
    smooth = Renderer(world.model, world.geom_entity, 640, 480, antialiasing=True)
    jagged = Renderer(world.model, world.geom_entity, 640, 480, antialiasing=False)
    try:
        for camera in backend.camera_names():
            depth, segmentation = _mujocos_own_depth_and_segmentation(world, camera)
            assert (segmentation >= 0).mean() > 0.5  # the table and the furniture fill most of every view
            for renderer in (smooth, jagged):
                one_depth, one_segmentation = renderer.depth_and_segmentation(data, camera)
                assert np.array_equal(one_depth, depth) and np.array_equal(one_segmentation, segmentation)
                assert np.array_equal(renderer.depth(data, camera), depth)
                assert np.array_equal(renderer.segmentation(data, camera), segmentation)
        # The model's own offscreen settings are left as they were (renders of other sizes need them).
        assert world.model.vis.quality.offsamples > 0 and world.model.vis.global_.offwidth > 640
    finally:
        smooth.close()
        jagged.close()
