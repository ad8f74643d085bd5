"""The retreats the tools make for a program: which of a program's own motions after a release count as its
retreat, and which leave the owed one to be made first."""

import math

import numpy as np

from roboscript.api.retreats import Owed
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend


def _tilted(degrees: float) -> np.ndarray:
    """Backing out of a grasp whose approach is tilted ``degrees`` off straight down: up and back."""
    a = math.radians(degrees)
    return np.array([0.0, -math.sin(a), math.cos(a)])


def test_rising_is_backing_out_only_within_20_degrees_of_a_tilted_release():
    # A UR5e let go of a cup gripped 39 degrees off vertical under its rim: the program's move straight up counted
    # as backing out (within the 60 degrees any retreat allows), and the fingers carried the cup up by its rim.
    with MujocoBackend("cluttered_2_pick_and_place", robot="ur5e", settle=0.3) as backend:
        retreats = build_tools(backend).retreats
        up = np.array([0.0, 0.0, 0.1])
        retreats.pending = Owed(_tilted(39.0), 0.03, "release", of_object=True)
        start = backend.tcp_pose().position
        assert retreats.first(up, shorter=True) is None  # the owed retreat was made first
        moved = backend.tcp_pose().position - start
        assert float(moved @ _tilted(39.0)) > 0.02
        for tilt in (0.0, 15.0):  # from above, or nearly along the way out: the program's move is its retreat
            retreats.pending = Owed(_tilted(tilt), 0.03, "release", of_object=True)
            assert retreats.first(up, shorter=True) is not None, tilt
        # A handle's bar leaves the fingers any way back: within the 60 degrees of any own retreat.
        retreats.pending = Owed(_tilted(39.0), 0.03, "release", of_object=False)
        assert retreats.first(up, shorter=True) is not None


def _hand(approach: np.ndarray, closing: np.ndarray) -> np.ndarray:
    """A hand's rotation from its approach (z) and closing (y) axes."""
    z = np.asarray(approach, dtype=float) / np.linalg.norm(approach)
    y = np.asarray(closing, dtype=float) - (np.asarray(closing) @ z) * z
    y /= np.linalg.norm(y)
    return np.column_stack([np.cross(y, z), y, z])


def test_a_hand_pitched_down_from_the_side_backs_out_level():
    from roboscript.api.retreats import _backing_out

    pitched = math.radians(29.0)
    side = np.array([math.cos(pitched), 0.0, -math.sin(pitched)])  # toward +x, 29 degrees down
    np.testing.assert_allclose(_backing_out(_hand(side, [0.0, 1.0, 0.0])), [-1.0, 0.0, 0.0], atol=1e-9)
    # From above, steeply down, or with the fingers closing up and down: back along the approach.
    for approach, closing in (([0, 0, -1], [0, 1, 0]), ([0.5, 0, -0.866], [0, 1, 0]), (side, [0.0, 0.0, 1.0])):
        rotation = _hand(np.array(approach, dtype=float), np.array(closing, dtype=float))
        np.testing.assert_allclose(_backing_out(rotation), -rotation[:, 2], atol=1e-9)


def test_a_cup_let_go_from_the_side_at_a_plates_near_edge_stays_on_the_plate():
    # Gripped level below its flared rim, the brown cup was lifted by the rim as the Panda's fingers backed out
    # along their pitched approach, and carried off the plate (paper task simple_1, seed 4, helpers style).
    from roboscript.bench.tasks import get_task
    from roboscript.sim.world_catalog import load_world

    world = load_world(get_task("simple_1").world).randomized(4)
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools, cup = build_tools(backend), "brown_ceramic_cup"
        tools.detect_objects()
        tools.open_gripper()
        tools.grasp(tools.parse_horizontal_grasp_pose(object_name=cup))
        tools.close_gripper()
        tools.attach_object(cup)
        tools.move_in_direction([0, 0, 1], 0.1)
        tools.move_to_pose(tools.parse_place_pose(object_name=cup, receptacle_name="white_ceramic_plate"))
        placed = backend.ground_truth.box(cup).center
        tools.open_gripper()
        tools.detach_object(cup)
        tools.move_in_direction([0, 0, 1], 0.1)
        left = backend.ground_truth.box(cup).center
        assert abs(left[2] - placed[2]) < 0.02 and np.linalg.norm(left[:2] - placed[:2]) < 0.03


def test_a_step_back_from_what_was_let_go_is_made_as_far_as_it_goes(caplog):
    """After letting go, the owed retreat is made first where the program's step is not one (73 degrees off it):
    that step, beyond the arm's reach in full, is made as far as it goes with a notice, not refused: the hand has
    left what it let go. Any other motion out of reach is still an IKError."""
    import pytest

    from roboscript.planning import IKError
    from roboscript.sim.world_file import parse_world

    world = parse_world({"name": "one_box", "objects": [{"name": "box", "type": "blue_box", "position": [0.1, 0.0]}]})
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        tools.detect_objects()
        tools.open_gripper()
        tools.grasp(tools.parse_central_lift_grasp_pose(object_name="box"))
        tools.close_gripper()
        tools.attach_object("box")
        tools.move_to_pose(tools.parse_place_pose(object_name="box", position=[0.1, 0.15, 0.0]))
        tools.open_gripper()
        tools.detach_object("box")
        start = backend.tcp_pose().position
        step = np.array([1.0, 0.0, 0.3]) / np.linalg.norm([1.0, 0.0, 0.3])
        with caplog.at_level("INFO"):
            tools.move_in_direction(step, 1.2)
        moved = backend.tcp_pose().position - start
        assert moved[2] > 0.04, "the owed retreat up was made"
        assert 0.05 < float(moved @ step) < 1.0, "then the step, part of the way"
        assert any("backed off" in r.getMessage() and "from what was let go" in r.getMessage() for r in caplog.records)
        with pytest.raises(IKError):
            tools.move_in_direction(step, 1.2)  # no longer a step back from anything
