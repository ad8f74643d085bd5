"""The planning scene built from what the cameras saw: it agrees with the simulator's geometry on which arm
configurations collide, carries objects, and is rebuilt when the world changed, keeping what was allowed and held."""

from __future__ import annotations

import contextlib

import numpy as np
import pytest

from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Box3D, Transform
from roboscript.perception.modes import parse_mode
from roboscript.planning.ground_truth_scene import ground_truth_scene
from roboscript.planning.perceived_scene import UNKNOWN, PerceivedSceneSource, filled_below, sort_points
from roboscript.robot_io import CameraFrame
from roboscript.robots import ROBOT_PREFIX
from roboscript.robots.panda import PANDA_DESCRIPTION
from roboscript.sim.world import robot_joint_readings


@pytest.fixture(scope="module")
def world():
    backend = MujocoBackend("world_2_pick_and_place", robot="panda")
    yield backend
    backend.close()


def test_the_perceived_scene_agrees_with_the_simulators_geometry(world):
    truth = ground_truth_scene(world.sim_world)
    api = build_tools(world, perception="gt-2d")
    scene = api.motion.scene
    assert {"apple", "footed_bowl", UNKNOWN} <= set(scene.body_labels)
    assert "table" not in scene.body_labels  # nothing named from the simulator's geometry: the table is seen
    state = api.motion.scene_source.state()
    readings = world.joint_states()  # by the names in the robot's own model, as a robot's driver reports them
    assert any("finger" in name for name in readings)  # the gripper's joints too: open fingers are wider
    assert set(readings) == {n.removeprefix(ROBOT_PREFIX) for n in robot_joint_readings(world.sim_world)()}
    for name, value in readings.items():
        assert state[scene.model.joint(ROBOT_PREFIX + name).qposadr[0]] == value
    scene.update(state)
    rng = np.random.default_rng(1)
    samples = [rng.uniform(truth.joint_lower, truth.joint_upper) for _ in range(300)]
    verdicts = [(truth.is_free(q), scene.is_free(q)) for q in samples]
    agreement = np.mean([a == b for a, b in verdicts])
    assert agreement >= 0.95, agreement
    assert sum(not a for a, _ in verdicts) > 30  # the sample does collide often enough to tell
    assert scene.is_free(world.joint_positions())


def test_a_rebuilt_scene_keeps_what_was_allowed_and_what_is_held(world):
    api = build_tools(world, perception="gt-2d")
    motion = api.motion
    first = motion.scene
    first.allow("gripper", "footed_bowl")
    motion.attach("apple")
    motion.world_changed()
    second = motion.scene
    assert second is not first and motion.scene_source.builds == 2
    assert second.attached == ["apple"]
    q = world.joint_positions()

    def held_pose(scene):  # the apple in the TCP's frame
        scene._place(q)
        body = scene.object_bodies["apple"]
        return scene.tcp_pose(q).inverse().apply(scene.data.xpos[body][None])[0]

    assert np.allclose(held_pose(first), held_pose(second), atol=1e-6)
    with_bowl = {pair for pair in first.allowed_names() if "footed_bowl" in pair}
    assert with_bowl and with_bowl <= second.allowed_names()  # what was allowed stays allowed
    assert motion.scene is second  # nothing changed since: no rebuild
    motion.detach("apple")


def test_points_near_an_object_are_its_own_and_parts_take_theirs():
    table = np.column_stack([np.linspace(-0.5, 0.5, 200), np.zeros(200), np.full(200, 0.82)])
    apple = np.array([[0.0, 0.0, 0.85], [0.02, 0.0, 0.87]])
    handle = np.array([[0.4, 0.0, 0.9]])
    contents = sort_points(
        np.vstack([table, apple, handle]),
        {"apple": apple},
        {"apple": Box3D(np.array([-0.03, -0.03, 0.82]), np.array([0.03, 0.03, 0.88]))},
        {
            "cabinet": Box3D(np.array([0.3, -0.2, 0.82]), np.array([0.6, 0.2, 1.2])),
            "cabinet.handle_0": Box3D(np.array([0.39, -0.01, 0.89]), np.array([0.41, 0.01, 0.91])),
        },
    )
    assert len(contents.fixed["cabinet.handle_0"]) == 1  # the smallest part box a point lies in takes it
    under = contents.fixed[UNKNOWN]
    assert np.any(np.abs(under[:, 0]) < 0.02)  # the table under the apple stays
    assert not (under[:, None, :] == apple[None, :, :]).all(axis=-1).any()  # no apple point is a fixed one
    assert not (under[:, None, :] == handle[None, :, :]).all(axis=-1).any()


@pytest.mark.parametrize(
    ("mode", "truth"),
    [
        ("gt", {"2d", "3d", "scene"}),
        ("full", set()),
        ("gt-2d", {"2d"}),
        ("gt-2d+gt-scene", {"2d", "scene"}),
        ("det-2d", {"scene"}),  # the earlier name of gt-scene, so that old run directories still resume
    ],
)
def test_modes_name_the_stages_taken_from_ground_truth(mode, truth):
    assert parse_mode(mode).from_truth == truth


def test_an_unknown_mode_lists_the_modes():
    for bad in ("gt-4d", "gt-2d+gt-2d", "2d", "gt+gt-2d"):
        with pytest.raises(ValueError, match=r"unknown perception mode .*modes: gt, full, gt-2d, gt-3d, gt-scene"):
            parse_mode(bad)
    assert parse_mode("gt-2d").needs_detector is False and parse_mode("gt-scene").needs_detector is True


class _StillPerception:
    """Test double: a perception whose only look shows a drawer front and a wall, with a camera frame that says
    nothing of them (no depth), so that whatever was remembered stays remembered."""

    looks = 1

    def __init__(self):
        self.front = np.column_stack([np.full(50, 0.4), np.linspace(0.2, 0.4, 50), np.full(50, 0.9)])
        self.wall = np.column_stack([np.full(50, 0.3), np.linspace(-0.4, -0.2, 50), np.full(50, 0.9)])
        self.visible = np.vstack([self.front, self.wall])
        self.boxes = {"cabinet.drawer_0": Box3D(np.array([0.38, 0.18, 0.88]), np.array([0.42, 0.42, 0.92]))}

    def objects(self):
        return []

    def furniture(self):
        return list(self.boxes)

    def box(self, name):
        return self.boxes[name]

    def joints(self, name):
        return []  # its handle was not seen: the drawer's joint cannot be told

    def scene_points(self):
        return self.visible

    def last_frames(self):
        k = np.array([[10.0, 0, 5], [0, 10.0, 5], [0, 0, 1]])
        return [CameraFrame("blind", None, np.full((10, 10), np.nan, np.float32), None, k, Transform.identity())]

    def last_masks(self):
        return [None]

    def without_looking(self):
        return contextlib.nullcontext()


class _StillDrawer(_StillPerception):
    """Test double: as :class:`_StillPerception`, with the drawer's joint told (it slides along -x to open)."""

    def joints(self, name):
        from roboscript.perception.base import ArticulationJoint

        if name != "cabinet.drawer_0":
            return []
        return [ArticulationJoint(name, "prismatic", np.array([0.4, 0.3, 0.9]), np.array([-1.0, 0, 0]), 0, 0, 0.3)]


@pytest.mark.parametrize("perception", [_StillPerception, _StillDrawer])
def test_what_was_seen_of_a_part_the_hand_moved_is_remembered_where_its_joint_took_it(perception):
    """A drawer pushed shut by 5 cm, the arm still at it, hiding it: remembered where it stood out, its front
    closed round the hand; forgotten, a door's handle hidden by the hand that let go of it was free space to hook.
    A part on a known joint is remembered where the hand's way along the joint took it (the hand's sideways
    drift is no part of it); one whose joint is not known is forgotten. The rest hidden stays where it was."""
    seen = perception()
    source = PerceivedSceneSource(seen, PANDA_DESCRIPTION, Transform.identity(), dict)
    source.contents()
    seen.visible = np.zeros((0, 3))  # the next look sees neither: the arm hides both
    source.mark_stale()
    remembered = source.contents()
    assert len(remembered.fixed["cabinet.drawer_0"]) == 50 and len(remembered.fixed[UNKNOWN]) == 50
    hand = (np.array([0.45, 0.3, 0.9]), np.array([0.50, 0.31, 0.9]))  # pushed 5 cm along +x, drifting 1 cm in y
    source.mark_stale(moved={"cabinet.drawer_0": hand, "cabinet.handle_0": hand})
    kept = np.vstack(list(source.contents().fixed.values()))
    if perception is _StillPerception:
        assert np.allclose(np.sort(kept, axis=0), np.sort(seen.wall, axis=0))  # the drawer forgotten, the wall kept
    else:
        pushed = seen.front + np.array([0.05, 0.0, 0.0])
        assert np.allclose(np.sort(kept, axis=0), np.sort(np.vstack([pushed, seen.wall]), axis=0))


def test_a_door_let_go_is_moved_by_the_turn_of_the_hand_about_its_hinge_not_by_the_hand_itself():
    from roboscript.geometry import quat_from_yaw
    from roboscript.perception.base import ArticulationJoint
    from roboscript.perception.furniture.articulation import part_motion

    hinge = ArticulationJoint("cabinet.door_0", "revolute", np.array([0.2, 0.4, 1.0]), np.array([0, 0, 1.0]), 0, 0, 2)
    hand_from = np.array([-0.1, 0.37, 1.1])  # at the handle, 30 cm from the hinge
    quarter = Transform(np.zeros(3), quat_from_yaw(np.pi / 2))
    hand_to = hinge.position + quarter.apply((hand_from - hinge.position)[None])[0]
    motion = part_motion(hinge, hand_from, hand_to)
    far_edge = np.array([0.19, 0.4, 1.05])
    assert np.allclose(motion.apply(np.vstack([hand_from, far_edge])), [hand_to, [0.2, 0.39, 1.05]], atol=1e-9)


def _inside_a_box(scene, body: str, point: np.ndarray) -> bool:
    model, data = scene.model, scene.data
    geoms = [g for g in range(model.ngeom) if model.body(model.geom_bodyid[g]).name == body]
    return any(np.all(np.abs(point - data.geom_xpos[g]) <= model.geom_size[g] + 1e-3) for g in geoms)


def test_a_cabinets_unseen_sides_and_back_are_solid_and_its_inside_free():
    """No camera sees the outer face of this cabinet's left side or its back; a thing carried past them must still
    find them in the way (the planning scene lays its panels), while the compartment behind its door stays free."""
    from roboscript.bench.tasks import get_task

    backend = MujocoBackend(get_task("into_cupboard.gen_083", suite="generated").world, robot="panda")
    try:
        api = build_tools(backend, perception="gt-2d")
        api.namespace()["detect_objects"]()
        scene = api.motion.scene
        truth = backend.ground_truth.box("cabinet")  # shut: its front at y = 0.37, its back at 0.73
        x_side, y_back = truth.lower[0] + 0.008, truth.upper[1] - 0.008
        for z in (0.9, 1.0, 1.1):
            for y in (0.45, 0.55, 0.65):
                assert _inside_a_box(scene, "fixed/cabinet", np.array([x_side, y, z])), (y, z)
            assert _inside_a_box(scene, "fixed/cabinet", np.array([0.0, y_back, z])), z
        assert not _inside_a_box(scene, "fixed/cabinet", np.array([0.0, 0.55, 1.1]))  # behind the door
        assert not _inside_a_box(scene, "fixed/cabinet", np.array([x_side - 0.03, 0.55, 1.0]))  # beside it
    finally:
        backend.close()


def test_each_column_is_filled_down_to_the_floor_from_its_own_lowest_point():
    step = 0.005
    # Two columns: one seen at 4 and 3 cm (filled from 3 cm down), one on the floor itself (nothing to fill).
    seen = np.array([[0.0012, 0.0031, 0.04], [0.0040, 0.0010, 0.03], [0.0121, 0.0021, 0.0]])
    filled = filled_below(seen, 0.0, step)
    assert np.array_equal(filled[:3], seen)
    fill = filled[3:]
    assert np.allclose(fill[:, :2], [0.0025, 0.0025])  # the first column's centre
    assert np.allclose(np.sort(fill[:, 2]), np.arange(0.0, 0.03, step))


def test_a_perceived_scene_holds_the_robots_colliding_geoms_only_and_all_of_them():
    import mujoco

    from roboscript.planning.perceived_scene import SceneContents, build_perceived_scene
    from roboscript.robots import get_robot
    from roboscript.robots.mujoco_model import compiled_robot

    for name in ("panda", "ur5e"):
        description = get_robot(name)
        mount = Transform(np.array([0.1, 0.2, 0.75]), np.array([0.0, 0.0, 0.0, 1.0]))
        scene = build_perceived_scene(description, mount, SceneContents({}, {}))
        full = compiled_robot(description, mount)
        collides = (full.geom_contype | full.geom_conaffinity) > 0

        def shapes(model, keep):
            body = [model.body(b).name for b in model.geom_bodyid[keep]]
            sizes = np.round(model.geom_size[keep], 9).tolist()
            return sorted(zip(body, model.geom_type[keep].tolist(), sizes, strict=True))

        model = scene.model
        assert ((model.geom_contype | model.geom_conaffinity) > 0).all()  # nothing that only draws
        assert shapes(model, np.ones(model.ngeom, bool)) == shapes(full, collides)
        assert model.nmesh < full.nmesh and model.nbody == full.nbody
        data, full_data = mujoco.MjData(model), mujoco.MjData(full)
        mujoco.mj_kinematics(model, data)
        mujoco.mj_kinematics(full, full_data)
        assert np.allclose(data.geom_xpos, full_data.geom_xpos[collides])


def test_a_part_with_a_perceived_joint_turns_on_it_with_its_handle_and_the_rest_stays():
    import mujoco

    from roboscript.perception.base import ArticulationJoint
    from roboscript.planning.perceived_scene import SceneContents, build_perceived_scene

    rng = np.random.default_rng(0)
    door = np.column_stack([rng.uniform(-0.18, 0.18, 400), np.full(400, 0.37), rng.uniform(1.0, 1.2, 400)])
    handle = np.column_stack([np.full(50, -0.13), np.full(50, 0.35), rng.uniform(1.08, 1.14, 50)])
    top = np.column_stack([rng.uniform(-0.2, 0.2, 200), rng.uniform(0.37, 0.7, 200), np.full(200, 1.21)])
    hinge = ArticulationJoint("cabinet.door_0", "revolute", np.array([0.185, 0.37, 1.1]), np.array([0, 0, 1.0]),
                              0.0, 0.0, np.pi / 2)  # fmt: skip
    contents = SceneContents(
        {},
        {"cabinet.door_0": door, "cabinet.handle_0": handle, "cabinet": top},
        {"cabinet.door_0": hinge, "cabinet.handle_0": hinge},
    )
    mount = Transform(np.array([0.0, -0.5, 0.75]), np.array([0.0, 0.0, 0.0, 1.0]))
    scene = build_perceived_scene(PANDA_DESCRIPTION, mount, contents)
    model, data = scene.model, scene.data
    labels = np.array(scene.body_labels)
    jointed = [b for b in np.flatnonzero(labels == "cabinet.door_0") if model.body_jntnum[b] > 0]
    assert len(jointed) == 1 and model.jnt_type[model.body_jntadr[jointed[0]]] == mujoco.mjtJoint.mjJNT_HINGE

    def centres(label):
        return data.geom_xpos[np.isin(model.geom_bodyid, np.flatnonzero(labels == label))].copy()

    mujoco.mj_kinematics(model, data)
    before = {name: centres(name) for name in ("cabinet.door_0", "cabinet.handle_0", "cabinet")}
    assert np.allclose(before["cabinet.handle_0"].mean(axis=0)[:2], [-0.13, 0.35], atol=0.01)
    data.qpos[model.jnt_qposadr[model.body_jntadr[jointed[0]]]] = np.pi / 2
    mujoco.mj_kinematics(model, data)
    turn = np.array([[0.0, -1.0], [1.0, 0.0]])  # a quarter turn about the vertical hinge
    for name in ("cabinet.door_0", "cabinet.handle_0"):
        expected = (before[name][:, :2] - hinge.position[:2]) @ turn.T + hinge.position[:2]
        assert np.allclose(centres(name)[:, :2], expected, atol=1e-9)
    assert np.array_equal(centres("cabinet"), before["cabinet"])  # the carcass stays


def test_the_padding_holds_between_a_surface_seen_as_many_boxes_and_a_finger_of_several_geoms():
    # MuJoCo's midphase prunes two bodies of several geoms each by their body margins. A perceived scene once left
    # those at zero: its padding (and a transfer's 2 cm clearance for what the hand holds) held against no observed
    # box, and a Panda planned a bar's carry under an opened door's bottom edge, seen 5 mm higher than it was.
    import mujoco

    from roboscript.planning.occupancy import OccupiedBox
    from roboscript.planning.perceived_scene import SceneContents, build_perceived_scene

    mount = Transform.identity()
    q = PANDA_DESCRIPTION.home_array()

    def scene_with_surface_at(top: float):
        def tiles(points, voxel):  # a 30 cm square of 2 cm tiles, 1 cm thick, whatever the points
            grid = np.arange(-0.15, 0.15, 0.02)
            corners = [(np.array([x, y, top - 0.01]), np.array([x + 0.02, y + 0.02, top])) for x in grid for y in grid]
            return [OccupiedBox(lower, upper) for lower, upper in corners]

        empty = build_perceived_scene(PANDA_DESCRIPTION, mount, SceneContents({}, {}))
        empty.place(q)
        centre = empty.tcp_pose(q).position
        contents = SceneContents({}, {"table": np.zeros((1, 3))})
        under_the_hand = Transform(-centre * [1, 1, 0], mount.quaternion)
        return build_perceived_scene(PANDA_DESCRIPTION, under_the_hand, contents, boxes_of=tiles)

    probe = scene_with_surface_at(0.0)
    probe.place(q)
    model, data = probe.model, probe.data
    table = np.isin(model.geom_bodyid, [b for b, name in enumerate(probe.body_labels) if name == "table"])
    assert table.sum() > 100
    arm = np.flatnonzero(probe.colliding_geoms & ~table)
    lowest = min(
        data.geom_xpos[g][2] - np.abs(data.geom_xmat[g].reshape(3, 3)[2]) @ model.geom_size[g]
        for g in arm
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX
    )
    assert 0.1 < lowest < 1.5  # the fingertips' pads, well above the surface at 0
    gap = 0.003  # inside the 5 mm padding
    near = scene_with_surface_at(lowest - gap)
    assert not near.is_free(q)
    assert any("table" in pair for pair in near.collisions(q))
    assert scene_with_surface_at(lowest - 0.02).is_free(q)
