"""The placement search: which pose, among those the arm reaches, sets a held thing down."""

from roboscript.api.placement import PLACE_LOW_LIFTS
from roboscript.api.spots import DROP
from roboscript.api.supports import floor_of
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.checks import on
from roboscript.bench.tasks import load_suite
from roboscript.sim.world_catalog import load_world


def test_a_short_drop_on_a_spot_beside_the_first_beats_a_long_one_on_it():
    # A cup held level by the UR5e's 8.5 cm gripper, its flared top 8.7 cm across: on the plate's first spot
    # the arm's links meet the table and the bowl unless the hand is 5 cm higher, and let go from there the cup
    # fell onto the open fingers and was carried off (sort_by_colour.gen_024, as its trials start).
    world = load_world(load_suite("generated")["sort_by_colour.gen_024"].world)
    with MujocoBackend(world, robot="ur5e", seed=0, randomize=True, settle=0.5) as backend:
        tools = build_tools(backend)
        tools.open_gripper()
        tools.grasp(tools.parse_horizontal_grasp_pose("red_cup"))
        tools.close_gripper()
        tools.attach_object("red_cup")
        tools.move_in_direction([0, 0, 1], 0.1)
        held = backend.ground_truth.box("red_cup")
        tcp = backend.tcp_pose().position
        pose = tools.parse_place_pose("red_cup", "red_plate")
        floor = floor_of(tools.perception.receptacle("red_plate"))
        released_at = held.lower[2] + (pose.position.z - tcp[2])  # the cup's bottom when the hand gets there
        assert released_at - floor < DROP + max(PLACE_LOW_LIFTS) + 0.01
        tools.move_to_pose(pose)
        tools.open_gripper()
        tools.detach_object("red_cup")
        tools.move_in_direction([0, 0, 1], 0.1)
        backend.wait(0.5)
        result = on("red_cup", "red_plate").evaluate(backend.ground_truth)
        assert result.passed, result.detail


def test_distinct_spots_drop_those_near_an_earlier_kept_one_turned_the_same_way_or_opposite():
    import math

    import numpy as np

    from roboscript.api.placement import _distinct
    from roboscript.api.spots import PlacementSpot

    rng = np.random.default_rng(3)
    yaws = rng.choice([0.0, 0.5, math.pi, 1.2], 400)
    centres = rng.uniform(0, 0.3, (400, 2))
    spots = [PlacementSpot(np.array([x, y, 0.8]), float(w), 0.0) for (x, y), w in zip(centres, yaws, strict=True)]
    spacing = 0.03
    expected: list = []
    for spot in spots:  # the definition, one pair at a time
        if not any(
            np.linalg.norm(spot.center - t.center) < spacing and abs(math.remainder(spot.yaw - t.yaw, math.pi)) < 0.1
            for t in expected
        ):
            expected.append(spot)
    kept = _distinct(spots, spacing)
    assert 20 < len(kept) < 300
    assert [id(s) for s in kept] == [id(s) for s in expected]
