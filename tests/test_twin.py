"""The twin of a scene as perceived: the table at the height the cameras measured, each described object where
they saw it with its modelled shape, an undescribed one as the box they saw, and the arm where the robot's is."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from roboscript.assembly import build_perception
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.objects import get_object_type
from roboscript.sim.world_catalog import load_world
from roboscript.twin import _placement, perceived_twin

WORLD = "world_2_pick_and_place"


def test_the_twin_holds_what_the_cameras_saw_where_they_saw_it():
    robot = MujocoBackend(WORLD, seed=3, randomize=True)  # stands in for the robot: the twin knows only the views
    twin = perceived_twin(load_world(WORLD), build_perception(robot, "gt-2d"))
    assert twin.left_out == {}
    assert abs(twin.world.table.height - 0.82) < 0.01
    truth = {o.name: o for o in robot.sim_world.spec.objects}
    assert twin.world.object_names() == ["apple", "footed_bowl"]
    for placed in twin.world.objects:
        assert placed.type is truth[placed.name].type  # described: the modelled shape, not a box
        assert np.linalg.norm(np.subtract(placed.position, truth[placed.name].position)) < 0.03
    start = robot.joint_positions() + 0.1
    copy = MujocoBackend(twin.world, "panda", start=start)
    assert np.abs(copy.joint_positions() - start).max() < 0.01
    assert "table top at 0.82" in twin.summary()


def test_an_object_the_description_does_not_name_becomes_the_box_that_was_seen():
    robot = MujocoBackend(WORLD)
    described = load_world(WORLD)
    without_bowl = replace(described, objects=described.objects[:1])
    perception = build_perception(robot, "gt-2d", scene=None)
    twin = perceived_twin(without_bowl, perception)
    bowl = next(o for o in twin.world.objects if o.name == "footed_bowl")
    assert bowl.type.name == "seen_footed_bowl" and bowl.type.category == "footed_bowl"
    true_size = get_object_type("footed_bowl").size
    assert np.allclose(sorted(bowl.type.size), sorted(true_size), atol=0.03)


def test_a_placement_puts_the_shape_s_footprint_centre_where_it_was_seen_and_its_long_side_along_the_seen_one():
    mug = get_object_type("white_mug")  # its handle makes its footprint off-centre in its own frame
    lower, upper = mug.bounds
    long_along_x = (upper - lower)[0] >= (upper - lower)[1]
    center, seen_half = np.array([0.1, -0.2]), np.array([0.02, 0.05]) if long_along_x else np.array([0.05, 0.02])
    placed = _placement("mug", mug, center, 0.3, seen_half)
    assert placed.yaw == pytest.approx(0.3 + np.pi / 2)  # seen long side along y: turned a quarter
    c, s = np.cos(placed.yaw), np.sin(placed.yaw)
    middle = (lower[:2] + upper[:2]) / 2
    turned = np.array([c * middle[0] - s * middle[1], s * middle[0] + c * middle[1]])
    assert np.allclose(np.array(placed.position) + turned, center)
