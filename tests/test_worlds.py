"""Every packaged world loads with both robots, settles and renders."""

import mujoco
import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.sim import world as world_module
from roboscript.sim.world import build_world
from roboscript.sim.world_catalog import load_world, world_names

ROBOTS = ("panda", "ur5e")


@pytest.fixture(scope="module", params=[(w, r) for w in world_names() for r in ROBOTS], ids=lambda p: f"{p[0]}-{p[1]}")
def settled(request):
    world, robot = request.param
    backend = MujocoBackend(world, robot=robot, settle=0.0)
    start = {n: backend.ground_truth.pose(n).position for n in backend.sim_world.entity_names(("object",))}
    took = backend.simulator.settle(max_duration=1.0)
    yield backend, start, took
    backend.close()


def test_objects_come_to_rest_within_one_second(settled):
    backend, start, took = settled
    assert took < 1.0, f"still moving after 1 s: speeds {backend.simulator.object_speeds().round(4).tolist()}"
    table_top = backend.sim_world.spec.table.height
    for name, position in start.items():
        now = backend.ground_truth.pose(name).position
        assert np.linalg.norm(now - position) < 0.02, f"{name} moved {np.linalg.norm(now - position):.3f} m"
        box = backend.ground_truth.box(name)
        assert box.lower[2] > table_top - 0.005, f"{name} sank into the table: bottom at {box.lower[2]:.4f}"
        assert np.all(np.isfinite(box.as_array()))


def test_world_renders_from_every_camera(settled):
    backend, _, _ = settled
    seen = set()
    for camera in backend.camera_names():
        frame = backend.capture(camera)
        assert frame.rgb.shape == (480, 640, 3) and frame.rgb.std() > 10
        h, w = frame.depth.shape
        centre = (slice(h // 4, 3 * h // 4), slice(w // 4, 3 * w // 4))
        table = backend.sim_world.entity("table").index
        on_table = frame.segmentation[centre] == table
        assert on_table.mean() > 0.3, f"{camera}: the table fills too little of the view's centre"
        table_depth = frame.depth[centre][on_table]
        assert 0.4 < np.median(table_depth) < 2.5, f"{camera}: table at {np.median(table_depth):.2f} m"
        assert np.all(frame.depth >= 0) and np.all(np.isfinite(frame.depth))
        seen |= {backend.sim_world.entities[i].name for i in np.unique(frame.segmentation) if i >= 0}
    objects = set(backend.sim_world.entity_names(("object",)))
    assert objects <= seen, f"not seen by any camera: {objects - seen}"


def test_robot_starts_at_home_with_the_gripper_open(settled):
    backend, _, _ = settled
    np.testing.assert_allclose(backend.joint_positions(), backend.robot.home_array(), atol=0.01)
    assert backend.gripper_width() == pytest.approx(backend.robot.gripper.max_width, abs=0.003)


def test_cabinet_parts_follow_the_api_names():
    world = load_world("world_5_mug_to_cabinet")
    assert world.part_names() == [
        "cabinet.drawer_0",
        "cabinet.handle_0",
        "cabinet.drawer_1",
        "cabinet.handle_1",
        "cabinet.drawer_2",
        "cabinet.handle_2",
        "cabinet.door_0",
        "cabinet.handle_3",
    ]


def _model_arrays(model: mujoco.MjModel) -> dict[str, np.ndarray]:
    arrays = {name: getattr(model, name) for name in dir(model) if not name.startswith("_")}
    arrays = {name: value.copy() for name, value in arrays.items() if isinstance(value, np.ndarray)}
    arrays["stat.extent"] = np.array([model.stat.extent])  # the renderer's clipping planes scale with it
    return arrays


def test_a_world_is_the_same_whichever_build_of_it_came_first():
    # A process keeps each world compiled and moves the objects for the next build (another seed): the model must
    # not depend on which layout was compiled.
    spec = load_world("world_3_mug_to_empty_plate")  # objects on the table and on other objects
    layouts = [spec.randomized(seed) for seed in (0, 1, 2)]
    built = []
    for first in layouts[:2]:
        world_module._compiled.clear()
        build_world(first, "panda")
        built.append(build_world(layouts[2], "panda"))
    world_module._compiled.clear()
    alone = build_world(layouts[2], "panda")
    for other in built:
        for name, value in _model_arrays(alone.model).items():
            np.testing.assert_array_equal(_model_arrays(other.model)[name], value, err_msg=name)
        np.testing.assert_array_equal(other.data.qpos, alone.data.qpos)
    # and the objects are where this layout put them, not where the compiled one had them
    moved = alone.model.body(next(o.name for o in spec.objects if o.support_kind == "table")).id
    assert not np.allclose(alone.model.body_pos[moved], build_world(layouts[0], "panda").model.body_pos[moved])
