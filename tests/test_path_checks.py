"""Path checks placed by how far the arm really travels: the bound holds, the checks find what a far denser
search finds, and they are far fewer than the lever-arm bound asks for."""

import numpy as np
import pytest

from helpers import ARMS
from helpers import DOWN_QUAT as DOWN
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform, quat_to_matrix
from roboscript.planning.ground_truth_scene import ground_truth_motion, ground_truth_scene
from roboscript.planning.path_checks import arm_travel, first_blocked
from roboscript.planning.planner import densify
from roboscript.sim.world_file import parse_world

ROBOTS = ARMS


def _holding_a_box(robot: str):
    """A scene whose arm holds a box hanging 15 cm below the fingers (the farthest point the bound must cover)."""
    world = parse_world(
        {
            "name": "held",
            "objects": [
                {"name": "held", "type": "cracker_box", "position": [0.1, -0.35]},
                {"name": "wall", "type": "cereal_box", "position": [0.05, 0.0], "yaw": 90},
            ],
        }
    )
    backend = MujocoBackend(world, robot=robot, settle=0.3)
    motion = ground_truth_motion(backend)
    qa = motion.ik(Transform(np.array([0.05, -0.25, 1.2]), DOWN))
    data, model = backend.sim_world.data, backend.sim_world.model
    state = data.qpos.copy()
    adr = model.jnt_qposadr[model.body_jntadr[model.body("held").id]]
    state[adr : adr + 3] = motion.kinematics.fk(qa).position - [0.0, 0.0, 0.15]
    state[adr + 3 : adr + 7] = [1.0, 0.0, 0.0, 0.0]
    state[backend.sim_world.robot.qpos] = qa
    motion.scene.update(state)
    motion.scene.attach("held", qa)
    return motion, qa


def _far_points(travel, rng, per_body: int = 12) -> list[np.ndarray]:
    """Per body, points on the sphere the bound allows for (its radius about its origin), in the body's frame."""
    out = []
    for radius in travel.radius:
        u = rng.normal(size=(per_body, 3))
        out.append(radius * u / np.linalg.norm(u, axis=1, keepdims=True))
    return out


def _path_lengths(scene, travel, local: list[np.ndarray], q0: np.ndarray, dq: np.ndarray, samples: int) -> float:
    """The longest path any of the points takes along the segment, measured at ``samples`` fine steps."""
    previous, longest = None, np.zeros(sum(len(p) for p in local))
    for s in np.linspace(0.0, 1.0, samples):
        scene.place(q0 + s * dq)
        xpos, xquat = travel.positions()
        world = np.concatenate(
            [x + p @ quat_to_matrix(np.roll(q, -1)).T for x, q, p in zip(xpos, xquat, local, strict=True)]
        )
        if previous is not None:
            longest += np.linalg.norm(world - previous, axis=1)
        previous = world
    return float(longest.max())


@pytest.mark.parametrize("robot", ROBOTS)
def test_the_travel_bound_holds_for_every_point_the_bodies_may_have(robot):
    motion, qa = _holding_a_box(robot)
    scene = motion.scene
    rng = np.random.default_rng(3)
    scene.place(qa)
    travel = arm_travel(scene)
    assert set(scene.held_bodies) <= set(travel.bodies.tolist())
    local = _far_points(travel, rng)
    span = scene.joint_upper - scene.joint_lower
    for size in (0.005, 0.02, 0.1, 0.4):
        for _ in range(6):
            q0 = np.clip(qa + rng.uniform(-0.5, 0.5, scene.dof), scene.joint_lower, scene.joint_upper)
            dq = rng.normal(size=scene.dof)
            dq *= size / np.abs(dq).sum()
            dq = np.clip(q0 + dq, scene.joint_lower, scene.joint_upper) - q0
            scene.place(q0)
            before = travel.positions()
            scene.place(q0 + dq)
            bound = travel.travel(before, travel.positions(), dq)
            actual = _path_lengths(scene, travel, local, q0, dq, 200)
            assert actual <= bound + 1e-9, (size, actual, bound)
            # And it is not the loose bound: within a few times the real travel for short segments.
            if size <= 0.02:
                assert bound < 3 * actual + 1e-3
    assert span.min() > 0


@pytest.mark.parametrize("robot", ROBOTS)
def test_what_the_checks_pass_is_free_of_contact_under_a_far_denser_search(robot):
    """Straight joint-space moves of the hand from one side of a standing box to the other, some over it and some
    through it: every move the checks pass has no point, in a search a millimetre fine, where the arm touches
    anything (the padding removed); every move they stop is stopped in a configuration that collides."""
    world = parse_world(
        {"name": "wall", "objects": [{"name": "wall", "type": "cereal_box", "position": [0.05, 0.0], "yaw": 90}]}
    )
    backend = MujocoBackend(world, robot=robot, settle=0.3)
    motion = ground_truth_motion(backend)
    bare = ground_truth_scene(backend.sim_world, padding=0.0)
    scene = motion.scene
    top = backend.ground_truth.box("wall").upper[2]
    rng = np.random.default_rng(5)
    passed = blocked = 0
    for _ in range(40):
        x0, x1 = rng.uniform(-0.05, 0.15, 2)
        z0, z1 = top + rng.uniform(-0.12, 0.08, 2)
        q0 = motion.ik(Transform(np.array([x0, -0.2, z0]), DOWN))
        q1 = motion.ik(Transform(np.array([x1, 0.2, z1]), DOWN), q0)
        found = first_blocked(scene, np.array([q0, q1]), scene.padding)
        fine = densify(np.array([q0, q1]), scene.lever_arms, 0.001)
        if found is None:
            passed += 1
            assert all(bare.is_free(q) for q in fine), "a move the checks passed touches something"
        else:
            blocked += 1
            assert not scene.is_free(found.q)
    assert passed >= 5 and blocked >= 5, (passed, blocked)


@pytest.mark.parametrize("robot", ROBOTS)
def test_a_cartesian_step_takes_a_fraction_of_the_lever_arm_checks(robot):
    motion, qa = _holding_a_box(robot)
    scene = motion.scene
    calls = []
    free = scene.is_free
    scene.is_free = lambda q: calls.append(1) or free(q)  # a counting wrapper (a test double around the real call)
    try:
        start = motion.kinematics.fk(qa)
        q, lever_checks = qa, 0
        for k in range(1, 21):  # 10 cm down in 5 mm steps
            target = Transform(start.position - [0.0, 0.0, 0.005 * k], start.quaternion)
            nxt = motion.kinematics.solve(target, q).q
            lever_checks += len(densify(np.array([q, nxt]), scene.lever_arms, scene.padding)) - 1
            assert first_blocked(scene, np.array([q, nxt]), scene.padding, check_start=False) is None
            q = nxt
    finally:
        del scene.is_free
    # A 5 mm step of the hand is checked at its end and once between (it moves the hand a hair more than the
    # padding); the lever-arm bound asks for twice that or more.
    assert len(calls) <= 2 * 20 < lever_checks, (len(calls), lever_checks)


def test_the_travel_is_measured_again_when_the_hand_holds_something_elsewhere():
    motion, qa = _holding_a_box("panda")
    scene = motion.scene
    scene.place(qa)
    held = arm_travel(scene)
    assert arm_travel(scene) is held  # nothing changed: the same one
    # The same box let go and taken again, now hanging 5 cm lower: the same body, a new bound.
    scene.detach("held")
    adr = scene.model.jnt_qposadr[scene.model.body_jntadr[scene.object_bodies["held"]]]
    state = scene.data.qpos.copy()
    state[adr + 2] -= 0.05
    scene.update(state)
    scene.attach("held", qa)
    scene.place(qa)
    lower = arm_travel(scene)
    assert lower is not held and lower.levers[-1] > held.levers[-1] + 0.04
    scene.detach("held")
    scene.place(qa)
    assert arm_travel(scene).levers[-1] < held.levers[-1]  # the bare hand reaches less far
