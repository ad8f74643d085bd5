"""parse_place_pose meets reasonable requests: stacking on any flat top, a position on a named receptacle, and a
position that is taken or out of reach moved to the nearest free, reachable spot within a stated bound."""

import logging

import numpy as np
import pytest

from roboscript.api.nearby import (
    NEAR_BASE,
    NEAREST_BOUND,
    Support,
    clear_of_base,
    finger_room_turns,
    free_spots,
    ranked,
    ring_candidates,
)
from roboscript.api.place_requests import PlacementError
from roboscript.api.spots import Footprint, gap
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform
from roboscript.perception.base import Receptacle
from roboscript.sim.world_file import parse_world


def _world(objects: list[dict]):
    return parse_world({"name": "place_requests", "objects": objects})


def _pick(tools, name: str) -> None:
    tools.open_gripper()
    tools.grasp(tools.parse_central_lift_grasp_pose(name, "center"))
    tools.close_gripper()
    tools.attach_object(name)
    tools.move_in_direction([0, 0, 1], 0.1)


def _put(tools, name: str, pose) -> None:
    tools.move_to_pose(pose)
    tools.open_gripper()
    tools.detach_object(name)
    tools.move_in_direction([0, 0, 1], 0.1)
    tools.backend.wait(0.5)


def test_ring_candidates_start_at_the_target_and_grow_outwards():
    points = ring_candidates(np.array([0.1, 0.2]), 0.06, np.array([-0.45, 0.0]))
    distances = np.linalg.norm(points - [0.1, 0.2], axis=1)
    assert distances[0] == 0.0
    assert np.all(np.diff(np.round(distances, 6)) >= 0)
    assert distances.max() == pytest.approx(0.06)


def test_free_spots_keep_clear_of_neighbours_and_on_the_support():
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    neighbour = Footprint(np.array([0.0, 0.0]), 0.0, np.array([0.04, 0.04]))
    support = Support(region, 0.8, (neighbour,))
    candidates = ring_candidates(np.array([0.03, 0.0]), NEAREST_BOUND, np.array([-0.45, 0.0]))
    spots = free_spots(candidates, np.array([0.025, 0.025]), 0.0, 0.05, support)
    # The target overlaps the neighbour: the first free spot is the nearest one clear of it.
    first = spots[0].center
    assert np.linalg.norm(first[:2] - [0.03, 0.0]) > 0.0
    assert first[0] >= 0.04 + 0.025 or abs(first[1]) >= 0.04 + 0.025
    assert first[2] == pytest.approx(0.8 + 0.025, abs=0.02)
    # Off the edge of the table: no spot beyond it.
    edge = free_spots(np.array([[0.6, 0.0]]), np.array([0.025, 0.025]), 0.0, 0.05, support)
    assert edge == []


def test_a_round_thing_fits_a_turned_basket_by_its_outline_not_its_turned_square():
    """An apple 7.6 cm across, 3 cm off the middle of a basket 16 cm wide whose sides are turned 22 degrees to
    the apple's axes: its square, turned so, would reach 5.9 cm from its middle towards the wall, past the wall's
    margin; the apple itself stays clear of it (measured.clear_table.gen_052: no spot in the basket within 30 cm
    of the asked one, though the basket's own spots had room)."""
    turn = np.radians(22.0)
    frame = Transform(np.array([0.0, 0.0, 0.82]), np.array([0.0, 0.0, np.sin(turn / 2), np.cos(turn / 2)]))
    basket = Receptacle("basket", frame, np.array([-0.15, -0.08, 0.008]), np.array([0.15, 0.08, 0.2]))
    support = Support(basket, 0.828, ())
    radius = 0.038
    angles = np.linspace(0.0, 2 * np.pi, 16, endpoint=False)
    outline = radius * np.column_stack([np.cos(angles), np.sin(angles)])
    half = np.array([radius, radius])
    across = frame.rotation[:2, 1]  # towards the basket's long wall
    off_middle = 0.03 * across[None]
    assert free_spots(off_middle, half, 0.0, 0.076, support) == [], "the turned square meets the wall's margin"
    (spot,) = free_spots(off_middle, half, 0.0, 0.076, support, outline)
    np.testing.assert_allclose(spot.center[:2], off_middle[0])
    # Beyond the room the outline leaves (8 cm less the radius and the margin: 3.5 cm), none.
    assert free_spots(0.04 * across[None], half, 0.0, 0.076, support, outline) == []


def test_a_taken_position_beside_a_neighbour_moves_along_it_not_away_from_it():
    """ "14 cm beside the mug", where a strawberry stands: the thing goes beside the strawberry, still as near the
    mug, rather than beyond the strawberry, which is as near the position but further from the mug."""
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    mug = Footprint(np.array([0.0, 0.0]), 0.0, np.array([0.045, 0.045]))
    strawberry = Footprint(np.array([0.0, 0.14]), 0.0, np.array([0.02, 0.02]))
    target, half = np.array([0.0, 0.14]), np.array([0.045, 0.045])  # 4 cm clear of the mug, with the margin
    support = Support(region, 0.8, (mug, strawberry))
    spots = free_spots(ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0])), half, 0.0, 0.08, support)
    assert spots[0].center[1] > 0.2  # nearest first: beyond the strawberry, away from the mug
    kept = ranked(spots, target, half, 0.0, support.obstacles)
    first = kept[0].center[:2]
    assert abs(first[0]) >= 0.02 + 0.045  # clear of the strawberry, beside it
    assert first[1] - 0.045 - 0.045 <= 0.14 - 0.09 + 0.02  # as near the mug as asked, within a ring
    assert sorted(tuple(s.center) for s in kept) == sorted(tuple(s.center) for s in spots)  # reordered, none lost


def test_a_neighbour_seven_centimetres_off_is_kept_as_near_when_the_position_is_taken():
    """ "Next to the mug", 7 cm clear of it, where a strawberry stands: 7 cm is beside it to a reader, so the thing
    goes beside the strawberry, not beyond it."""
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    mug = Footprint(np.array([0.0, 0.0]), 0.0, np.array([0.045, 0.045]))
    target, half = np.array([0.0, 0.045 + 0.07 + 0.045]), np.array([0.045, 0.045])
    strawberry = Footprint(target, 0.0, np.array([0.02, 0.02]))
    support = Support(region, 0.8, (mug, strawberry))
    spots = free_spots(ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0])), half, 0.0, 0.08, support)
    first = ranked(spots, target, half, 0.0, support.obstacles)[0].center[:2]
    assert abs(first[0]) >= 0.02 + 0.045  # clear of the strawberry, beside it
    assert first[1] - 0.09 <= 0.07 + 0.02  # as near the mug as asked, within a ring


def test_a_round_neighbours_outline_not_its_rectangle_decides_whether_a_position_is_free():
    """A can 1.5 cm from a bowl, diagonally: their rectangles overlap at the corners, the things do not."""
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    angles = np.arange(32) * 2 * np.pi / 32
    circle = np.column_stack([np.cos(angles), np.sin(angles)])
    bowl = Footprint(np.zeros(2), 0.0, np.array([0.04, 0.04]), 0.04 * circle)
    half, can = np.array([0.03, 0.03]), 0.03 * circle
    target = np.array([1.0, 1.0]) * (0.04 + 0.015 + 0.03) / np.sqrt(2)
    support = Support(region, 0.8, (bowl,))
    candidates = ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0]))
    by_rectangles = free_spots(candidates, half, 0.0, 0.1, support)
    assert np.linalg.norm(by_rectangles[0].center[:2] - target) > 0.01, "the rectangles overlap"
    by_outlines = free_spots(candidates, half, 0.0, 0.1, support, can)
    assert np.allclose(by_outlines[0].center[:2], target), "the can itself stands clear"
    # Nearer than the margin, the outlines do not stand clear either.
    touching = np.array([1.0, 1.0]) * (0.04 + 0.003 + 0.03) / np.sqrt(2)
    assert free_spots(touching[None], half, 0.0, 0.1, support, can) == []


def test_a_mugs_outline_is_its_body_and_handle_within_its_footprint():
    world = _world([{"name": "red_mug", "type": "red_mug", "position": [0.1, 0.0], "yaw": 35}])
    with MujocoBackend(world, robot="panda", settle=0.2) as backend:
        perception = build_tools(backend).perception
        center, yaw, half = perception.footprint("red_mug")
        outline = perception.outline("red_mug")
    axes = np.array([[np.cos(yaw), np.sin(yaw)], [-np.sin(yaw), np.cos(yaw)]])
    local = (outline - center) @ axes.T
    assert np.all(np.abs(local) <= half + 1e-6), "within the footprint"
    area = 0.5 * abs(
        np.dot(outline[:, 0], np.roll(outline[:, 1], -1)) - np.dot(outline[:, 1], np.roll(outline[:, 0], -1))
    )
    assert area < 0.9 * 4 * half[0] * half[1], "the corners of its rectangle are not the mug's"


@pytest.mark.parametrize("round_bottle", [False, True], ids=["rectangles", "outlines"])
def test_a_position_moved_off_what_stood_there_leaves_the_fingers_room_to_take_the_thing_again(round_bottle):
    """A gelatin box asked to go where a medication bottle stands (overlapping it by 2 cm, so taken for a
    neighbour): it moves along the bottle, but not snug against it across its narrow side, where the fingers close
    to take it again; the turns kept are those that leave that room. Measured between outlines, the round bottle
    stands further from a spot beside it than its rectangle does: the room kept for the fingers is not counted as
    moving away from it."""
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    angles = np.arange(24) * 2 * np.pi / 24
    circle = 0.022 * np.column_stack([np.cos(angles), np.sin(angles)]) if round_bottle else None
    bottle = Footprint(np.array([0.0, 0.0]), 0.0, np.array([0.022, 0.022]), circle)
    half = np.array([0.045, 0.036])  # narrow along y: the fingers close along y
    box = Footprint(np.zeros(2), 0.0, half).shape() if round_bottle else None
    target = np.array([0.0, 0.022 + 0.036 + 0.007 - 0.02])
    support = Support(region, 0.8, (bottle,))
    candidates = ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0]))
    spots = free_spots(candidates, half, 0.0, 0.03, support, box)
    first = ranked(spots, target, half, 0.0, support.obstacles, None, box)[0]
    assert finger_room_turns(first, half, 0.0, support.obstacles) == first.turns
    for turn in first.turns:
        # The open fingers (2 cm square pads, 1 cm out from each long side) come down across the narrow side.
        closing = np.array([-np.sin(turn), np.cos(turn)])  # the box's own y axis, turned
        for side in (-1.0, 1.0):
            pad = Footprint(first.center[:2] + side * closing * (half[1] + 0.01 + 0.01), turn, np.array([0.01, 0.01]))
            assert gap(pad, bottle) > 0.0, f"a finger comes down on the bottle (turn {turn:.2f})"
    assert np.linalg.norm(first.center[:2] - target) <= 0.08, "not sent far off for it"


@pytest.mark.parametrize("yaw", [0.3, 0.6, 1.2])
def test_a_turned_box_moved_off_a_round_bottle_it_was_asked_onto_keeps_a_fingers_room_from_it(yaw):
    """Outline to outline, a spot with room for the fingers between the box and the bottle stands a few
    centimetres further from the bottle than a snug one: that room is what "beside it" means for a thing the
    position overlapped, not a move away from it (a gelatin box put 7 mm from a bottle could not be taken again)."""
    region = Receptacle("table", Transform.identity(), np.array([-0.5, -0.5, 0.8]), np.array([0.5, 0.5, 1.2]))
    angles = np.arange(24) * 2 * np.pi / 24
    target, half = np.array([-0.07, -0.09]), np.array([0.045, 0.037])
    box = Footprint(np.zeros(2), yaw, half).shape()
    for offset in ([-0.035, 0.017], [0.0, 0.045], [0.03, -0.03]):
        middle = target + offset
        bottle = Footprint(
            middle, 0.0, np.array([0.022, 0.022]), middle + 0.022 * np.column_stack([np.cos(angles), np.sin(angles)])
        )
        support = Support(region, 0.8, (bottle,))
        spots = free_spots(
            ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0])), half, yaw, 0.03, support, box
        )
        first = ranked(spots, target, half, yaw, support.obstacles, None, box)[0]
        assert finger_room_turns(first, half, yaw, support.obstacles), (offset, first.center)
        assert np.linalg.norm(first.center[:2] - target) <= 0.08, "not sent far off for it"


def test_stacking_on_a_box_that_is_no_container():
    world = _world(
        [
            {"name": "red_block", "type": "red_block", "position": [0.0, -0.15]},
            {"name": "gelatin_box", "type": "gelatin_box", "position": [0.05, 0.1]},
        ]
    )
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        _pick(tools, "red_block")
        _put(tools, "red_block", tools.parse_place_pose("red_block", "gelatin_box"))
        block, box = backend.ground_truth.box("red_block"), backend.ground_truth.box("gelatin_box")
        assert block.lower[2] > box.upper[2] - 0.01
        assert np.linalg.norm(block.center[:2] - box.center[:2]) < 0.02


def test_a_ball_has_no_top_to_stack_on():
    world = _world(
        [
            {"name": "red_block", "type": "red_block", "position": [0.0, -0.15]},
            {"name": "baseball", "type": "baseball", "position": [0.05, 0.1]},
        ]
    )
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        _pick(tools, "red_block")
        with pytest.raises(ValueError, match="'baseball' cannot hold things: it has no interior and no flat top"):
            tools.parse_place_pose("red_block", "baseball")


def test_a_position_on_a_named_receptacle_and_a_taken_one_moved_aside(caplog):
    world = _world(
        [
            {"name": "apple", "type": "apple", "position": [0.0, -0.2]},
            {"name": "white_plate", "type": "white_plate", "position": [0.05, 0.12]},
            {"name": "red_box", "type": "red_box", "position": [0.15, -0.1]},
        ]
    )
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        gt = backend.ground_truth
        _pick(tools, "apple")
        # Both given: the position, on the plate (its height), not the plate's own choice of spot.
        plate = gt.box("white_plate")
        target = plate.center + np.array([0.02, 0.0, 0.3])
        with caplog.at_level(logging.INFO, logger="roboscript.notices"):
            pose = tools.parse_place_pose("apple", "white_plate", position=target)
        assert not caplog.records
        _put(tools, "apple", pose)
        apple = gt.box("apple")
        assert np.linalg.norm(apple.center[:2] - target[:2]) < 0.02
        assert apple.lower[2] > plate.lower[2] and apple.lower[2] < plate.upper[2] + 0.01
        # Where the red box stands: moved to the nearest free spot, and the move is told.
        _pick(tools, "apple")
        box = gt.box("red_box").center
        with caplog.at_level(logging.INFO, logger="roboscript.notices"):
            pose = tools.parse_place_pose("apple", position=box + np.array([0.04, 0.0, 0.0]))
        assert any("cm away" in r.getMessage() for r in caplog.records)
        _put(tools, "apple", pose)
        apple = gt.box("apple")
        moved = np.linalg.norm(apple.center[:2] - box[:2] - np.array([0.04, 0.0]))
        assert 0.0 < moved <= NEAREST_BOUND + 0.015
        assert apple.lower[2] < gt.box("table").upper[2] + 0.02  # on the table, not on the box


def test_no_free_spot_within_the_bound_says_how_far_the_nearest_is():
    world = _world(
        [
            {"name": "apple", "type": "apple", "position": [0.0, -0.2]},
            {"name": "basket", "type": "basket", "position": [0.05, 0.15]},
        ]
    )
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        _pick(tools, "apple")
        # 15 cm past the edge of the table (y up to 0.9 m): the nearest spot on it is further than 15 cm.
        with pytest.raises(PlacementError, match=r"within 15 cm.*the nearest free spot on 'table' is \d+ cm away"):
            tools.parse_place_pose("apple", position=[0.0, 1.05, 0.0])


def test_a_position_over_a_saucer_with_no_room_on_it_is_moved_onto_the_table_beside_it(caplog):
    # A temporary spot a program chose fell on a saucer (nothing named), and a lime takes the room on it.
    world = _world(
        [
            {"name": "toy_car", "type": "toy_car", "position": [0.1, -0.2]},
            {"name": "pink_saucer", "type": "pink_saucer", "position": [0.0, 0.1]},
            {"name": "lime", "type": "lime", "on": "pink_saucer", "position": [0.0, 0.0]},
        ]
    )
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        gt = backend.ground_truth
        tools.open_gripper()
        tools.grasp(tools.parse_adaptive_shape_grasp_pose("toy_car", preferred_approach_direction=[0, 0, -1]))
        tools.close_gripper()
        tools.attach_object("toy_car")
        tools.move_in_direction([0, 0, 1], 0.1)
        saucer = gt.box("pink_saucer").center
        with caplog.at_level(logging.INFO, logger="roboscript.notices"):
            pose = tools.parse_place_pose("toy_car", position=saucer)
        assert any("cm away" in r.getMessage() for r in caplog.records)
        _put(tools, "toy_car", pose)
        car = gt.box("toy_car")
        assert car.lower[2] < gt.box("table").upper[2] + 0.01  # on the table, beside the saucer
        assert np.linalg.norm(car.center[:2] - saucer[:2]) <= NEAREST_BOUND + 0.02


def test_bowls_and_baskets_have_walls_plates_and_saucers_do_not():
    from roboscript.api import supports

    world = _world([
        {"name": "white_plate", "type": "white_plate", "position": [0.0, 0.25]},
        {"name": "pink_saucer", "type": "pink_saucer", "position": [0.0, -0.25]},
        {"name": "red_bowl", "type": "red_bowl", "position": [0.2, 0.0]},
        {"name": "basket", "type": "basket", "position": [-0.15, 0.0]},
    ])  # fmt: skip
    with MujocoBackend(world, robot="panda", settle=0.5) as backend:
        perception = build_tools(backend).perception
        walls = {n: supports.has_walls(perception, supports.holds(perception, n)) for n in perception.objects()}
        assert walls == {"white_plate": False, "pink_saucer": False, "red_bowl": True, "basket": True}


def test_the_doc_string_gives_the_distances_the_placement_keeps():
    # A program reads how far a thing put aside goes from where it stood, and how far a taken position may move:
    # the words must be the code's.
    import inspect

    from roboscript.api.place_requests import ASIDE_AWAY
    from roboscript.api.tools import ToolAPI

    doc = " ".join(inspect.getdoc(ToolAPI.parse_place_pose).split())
    assert f"at least {ASIDE_AWAY * 100:.0f} cm from where it stood" in doc
    assert f"spot within {NEAREST_BOUND * 100:.0f} cm" in doc
    assert f"within {NEAR_BASE * 100:.0f} cm of the robot's base" in doc


def test_a_thing_sent_away_from_where_it_was_taken_is_not_brought_back_when_its_position_is_taken():
    """A toy car sent 20 cm towards the robot, onto a saucer with no room for it: beside the saucer, but not back
    towards the place it was taken from (where a swap's next object goes)."""
    region = Receptacle("table", Transform.identity(), np.array([-0.6, -0.6, 0.8]), np.array([0.6, 0.6, 1.2]))
    origin = np.array([-0.1, 0.0])  # the middle of the reach (0.5 m from the base) lies beyond it
    target = origin + np.array([-0.2, 0.0])
    saucer = Footprint(target, 0.0, np.array([0.08, 0.08]))
    half = np.array([0.04, 0.055])
    support = Support(region, 0.8, (saucer,))
    spots = free_spots(ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0])), half, 0.0, 0.045, support)
    back = ranked(spots, target, half, 0.0, support.obstacles)[0]
    assert np.linalg.norm(back.center[:2] - origin) < 0.15, "without the origin, the nearest spot is back towards it"
    first = ranked(spots, target, half, 0.0, support.obstacles, origin)[0]
    assert np.linalg.norm(first.center[:2] - origin) >= 0.2 - 0.02
    assert np.linalg.norm(first.center[:2] - target) <= NEAREST_BOUND


def test_a_thing_carried_far_from_where_it_was_taken_is_placed_as_if_the_place_were_unknown():
    """Only coming back near the old place counts: spots in a drawer 70 cm from where a box was taken keep their
    order (the front of the drawer, nearer that place, is where things go)."""
    region = Receptacle("table", Transform.identity(), np.array([-0.6, -0.6, 0.8]), np.array([0.6, 0.6, 1.2]))
    target, half = np.array([0.0, 0.0]), np.array([0.04, 0.04])
    support = Support(region, 0.8, (Footprint(target, 0.0, np.array([0.05, 0.05])),))
    spots = free_spots(ring_candidates(target, NEAREST_BOUND, np.array([-0.45, 0.0])), half, 0.0, 0.05, support)
    alone = ranked(spots, target, half, 0.0, support.obstacles)
    far = ranked(spots, target, half, 0.0, support.obstacles, np.array([0.0, -0.7]))
    assert [tuple(s.center) for s in far] == [tuple(s.center) for s in alone]


def test_a_position_beside_the_base_moves_out_to_where_the_arm_can_take_the_thing_again():
    """A pear sent 20 cm towards the robot, 12 cm from the base's axis: put down there, the Panda could lift it
    again only 3 cm, its wrist at a joint limit. It goes to the nearest free spot at least NEAR_BASE out, within
    the bound; a position further out keeps the order of its spots."""
    base = np.array([-0.45, 0.0])
    region = Receptacle("table", Transform.identity(), np.array([-0.6, -0.6, 0.8]), np.array([0.6, 0.6, 1.2]))
    support, half = Support(region, 0.8, ()), np.array([0.035, 0.035])
    target = base + np.array([0.12, -0.03])
    spots = free_spots(ring_candidates(target, NEAREST_BOUND, base), half, 0.0, 0.1, support)
    near = ranked(spots, target, half, 0.0, support.obstacles)
    assert np.allclose(near[0].center[:2], target), "the position itself is free"
    first = clear_of_base(near, base)[0]
    assert np.linalg.norm(first.center[:2] - base) >= NEAR_BASE
    assert np.linalg.norm(first.center[:2] - target) <= NEAR_BASE - 0.12 + 0.03, "not sent further than needed"
    assert sorted(tuple(s.center) for s in clear_of_base(near, base)) == sorted(tuple(s.center) for s in near)
    out = base + np.array([0.35, 0.0])
    spots = ranked(free_spots(ring_candidates(out, 0.1, base), half, 0.0, 0.1, support), out, half, 0.0, ())
    assert clear_of_base(spots, base) == spots


def test_what_stands_under_a_spot_looks_again_at_no_drawer_far_from_it():
    """What a thing put down at a position rests on is asked of a drawer's inside (a question that, in full
    perception, looks again first where the arm has moved: a second) only where the inside as already measured
    comes within INSIDE_SLACK of the position. A test double of ground truth counts those questions."""
    import mujoco

    from roboscript.api.supports import INSIDE_SLACK, contains_xy, support_under
    from roboscript.perception.ground_truth import GroundTruthPerception

    class CountsQuestions(GroundTruthPerception):
        def __init__(self, backend):
            super().__init__(backend)
            self.asked: list[str] = []

        def receptacle(self, name):  # the question that may look again
            self.asked.append(name)
            return super().receptacle(name)

        def seen_receptacle(self, name):  # the one that never does
            return super().receptacle(name)

    with MujocoBackend("world_1_table_sort", robot="panda") as backend:
        model, data = backend.sim_world.model, backend.sim_world.data
        data.qpos[model.joint("cabinet.drawer_1.joint").qposadr[0]] = 0.2
        mujoco.mj_forward(model, data)
        perception = CountsQuestions(backend)
        drawer = perception.seen_receptacle("cabinet.drawer_1")
        inside = drawer.frame.apply(np.array([(drawer.lower + drawer.upper) / 2]))[0, :2]
        far = np.array([0.0, -0.45])  # on the table, clear of everything, 80 cm from the cabinet
        assert not contains_xy(drawer, far, INSIDE_SLACK)
        half = np.array([0.03, 0.03])

        assert support_under(perception, "none", far, half).region.name == "table"
        assert not [name for name in perception.asked if name.startswith("cabinet.")]
        assert support_under(perception, "none", inside, half).region.name == "cabinet.drawer_1"
        assert "cabinet.drawer_1" in perception.asked
