"""A drawer's inside measured from points: on a drawer built here from sampled surfaces (its front, bottom, walls
and the carcass around it), and on the simulated cabinet against the simulator's tray geometry."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.assembly import build_perception
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.base import DRAWER_FRONT_CLEARANCE, ArticulationJoint
from roboscript.perception.furniture.drawers import carcass_front, closed_drawer, drawer_receptacle, opening_frame

RNG = np.random.default_rng(3)


def _sheet(corner, u, v, n: int = 1500, normal=(0.0, 0.0, 1.0)) -> np.ndarray:
    """Points spread over the rectangle ``corner + s u + t v``, each with the ``normal`` it faces: (n, 6)."""
    s, t = RNG.random((2, n))
    points = np.asarray(corner) + s[:, None] * np.asarray(u) + t[:, None] * np.asarray(v)
    return np.hstack([points, np.tile(normal, (n, 1))])


def _drawer(opening: float) -> tuple[np.ndarray, np.ndarray]:
    """A drawer in a carcass whose front stands at x = 0, opening along +x by ``opening``: (drawer points,
    carcass points), each row a point and its normal. Inside: 40 cm deep, 36 cm wide, 10 cm walls, bottom at z = 1.0."""
    front_x = opening
    drawer = [
        _sheet([front_x, -0.2, 0.98], [0, 0.4, 0], [0, 0, 0.14], normal=(1, 0, 0)),  # the front's outer face
        _sheet([front_x - 0.015, -0.2, 1.12], [0.015, 0, 0], [0, 0.4, 0], 400),  # its top edge: 1.5 cm thick
    ]
    if opening > 0:  # the bottom and walls, seen where they stand out of the carcass (and a little beyond)
        back = front_x - 0.4
        drawer += [
            _sheet([back, -0.18, 1.0], [0.4 - 0.015, 0, 0], [0, 0.36, 0]),
            _sheet([back, -0.18, 1.0], [0.4 - 0.015, 0, 0], [0, 0, 0.1], 600, normal=(0, 1, 0)),  # the walls' insides
            _sheet([back, 0.18, 1.0], [0.4 - 0.015, 0, 0], [0, 0, 0.1], 600, normal=(0, -1, 0)),
            _sheet([back, -0.19, 0.99], [0.4 - 0.015, 0, 0], [0, 0, 0.11], 600, normal=(0, -1, 0)),  # an outside
        ]
    carcass = np.concatenate(
        [
            _sheet([0.0, -0.22, 0.96], [0, 0.44, 0], [0, 0, 0.02], 800),  # the front frame under the drawer
            _sheet([0.0, -0.22, 1.14], [0, 0.44, 0], [0, 0, 0.02], 800),  # and above it
            _sheet([-0.5, -0.22, 0.9], [0.5, 0, 0], [0, 0, 0.5], 3000, normal=(0, -1, 0)),  # a side panel
            _sheet([-0.5, -0.22, 1.4], [0.5, 0, 0], [0, 0.44, 0], 3000),  # the top
        ]
    )
    return np.concatenate(drawer), carcass


def _joint(opening: float) -> ArticulationJoint:
    """The drawer's joint as estimated: through the handle's foot on the front."""
    axis = np.array([1.0, 0.0, 0.0])
    return ArticulationJoint("cabinet.drawer_0", "prismatic", np.array([opening, 0.0, 1.065]), axis, 0.0, 0.0, 0.3)


def test_an_open_drawers_inside_reaches_back_to_the_carcass_only():
    drawer, carcass = _drawer(opening=0.25)
    frame = opening_frame(_joint(0.25))
    line = carcass_front(carcass[:, :3], frame, 0.35)
    assert line == pytest.approx(-0.25, abs=0.006)  # the carcass's front frame, not its side or top
    inside = drawer_receptacle("cabinet.drawer_0", drawer[:, :3], drawer[:, 3:], frame, line)
    lower, upper = (frame.apply(v[None])[0] for v in (inside.lower, inside.upper))
    assert lower[0] == pytest.approx(DRAWER_FRONT_CLEARANCE, abs=0.01)  # not the part still in the carcass
    assert upper[0] == pytest.approx(0.25 - 0.015, abs=0.002)  # up to the front panel's inner face
    # Between the walls' inner faces: the outside of a wall reaches the floor's height too, but does not face up.
    assert lower[1] == pytest.approx(-0.18, abs=0.004) and upper[1] == pytest.approx(0.18, abs=0.004)
    assert lower[2] == pytest.approx(1.0, abs=0.002)


def test_the_carcass_front_is_its_tops_front_edge_where_the_top_was_seen():
    """The frame around the drawers seen as a few thin strips, and the pulled drawer's back wall, inside the
    carcass, as a dense layer: the densest layer alone would put the carcass's front at the back wall (a drawer
    pulled out 15 cm read as 30 cm, and a program pushing it shut by that much was refused half-way)."""
    _, carcass = _drawer(opening=0.15)
    thin_frame = carcass[:1600][RNG.random(1600) < 0.03]
    back_wall = _sheet([0.15 - 0.3, -0.18, 1.0], [0, 0.36, 0], [0, 0, 0.1], 2000, normal=(1, 0, 0))
    seen = np.concatenate([thin_frame, carcass[1600:], back_wall])
    frame = opening_frame(_joint(0.15))
    assert carcass_front(seen[:, :3], frame, 0.35) == pytest.approx(-0.3, abs=0.006)  # points alone: the wall
    assert carcass_front(seen[:, :3], frame, 0.35, seen[:, 3:]) == pytest.approx(-0.15, abs=0.006)


def test_a_closed_drawer_shows_no_inside_and_has_no_room():
    drawer, carcass = _drawer(opening=0.0)
    frame = opening_frame(_joint(0.0))
    line = carcass_front(carcass[:, :3], frame, 0.35)
    assert drawer_receptacle("cabinet.drawer_0", drawer[:, :3], drawer[:, 3:], frame, line) is None
    closed = closed_drawer("cabinet.drawer_0", drawer[:, :3], frame)
    assert closed.upper[0] - closed.lower[0] == 0.0
    assert closed.lower[1] == pytest.approx(-0.2, abs=0.01) and closed.upper[1] == pytest.approx(0.2, abs=0.01)


def test_a_bottom_seen_only_along_one_wall_is_not_an_inside():
    """The arm hid all of an open drawer's bottom but a 1 cm strip along one wall: too narrow to be an inside."""
    frame = opening_frame(_joint(0.25))
    strip = _sheet([-0.15, -0.18, 1.0], [0.385, 0, 0], [0, 0.01, 0], 400)
    wall = _sheet([-0.15, -0.18, 1.0], [0.385, 0, 0], [0, 0, 0.1], 600, normal=(0, 1, 0))
    seen = np.concatenate([strip, wall])
    assert drawer_receptacle("cabinet.drawer_0", seen[:, :3], seen[:, 3:], frame, -0.25) is None
    whole = np.concatenate([seen, _sheet([-0.15, -0.18, 1.0], [0.385, 0, 0], [0, 0.36, 0])])
    assert drawer_receptacle("cabinet.drawer_0", whole[:, :3], whole[:, 3:], frame, -0.25) is not None


def test_the_tops_of_two_walls_are_not_a_bottom():
    """Seen from above with the bottom hidden, the walls' top edges are two level lines as far apart as the
    drawer is wide: they cover too little of the rectangle between them to be its bottom."""
    frame = opening_frame(_joint(0.25))
    tops = np.concatenate([_sheet([-0.15, y, 1.1], [0.385, 0, 0], [0, 0.008, 0], 800) for y in (-0.188, 0.18)])
    assert drawer_receptacle("cabinet.drawer_0", tops[:, :3], tops[:, 3:], frame, -0.25) is None


def test_a_joint_that_does_not_slide_level_is_refused():
    joint = ArticulationJoint("cabinet.drawer_0", "prismatic", np.zeros(3), np.array([0.0, 0, 1]), 0, 0, 0.3)
    with pytest.raises(ValueError, match="not a drawer's level axis"):
        opening_frame(joint)


def test_the_seen_inside_of_the_simulated_drawer_matches_its_tray():
    """Closed, no room. Then pulled out 22 cm and let go of (as the tools tell perception after a pull): it looks
    again, and the inside from points matches the simulator's tray (less the part in the carcass)."""
    backend = MujocoBackend("cluttered_5_mug_to_cabinet", robot="panda")
    try:
        seen = build_perception(backend, "gt-2d")
        closed = seen.receptacle("cabinet.drawer_1")
        assert closed.upper[0] - closed.lower[0] < 0.04
        world = backend.sim_world
        body = world.entity("cabinet.drawer_1").bodies[0]
        world.data.qpos[world.model.jnt_qposadr[world.model.body_jntadr[body]]] = 0.22
        backend.wait(0.2)
        truth = build_perception(backend, "gt")
        looks = seen.looks
        seen.released("cabinet.drawer_1", backend.tcp_pose())
        expected, found = truth.receptacle("cabinet.drawer_1"), seen.receptacle("cabinet.drawer_1")
        corners = [(r.frame.apply(r.lower[None])[0], r.frame.apply(r.upper[None])[0]) for r in (expected, found)]
        (lower, upper), (seen_lower, seen_upper) = corners
        # Within the tray (3 mm allowed), and short of it by at most 1.5 cm (a wall's shadow hides the bottom
        # beside it from a camera on its side).
        inward = np.concatenate([seen_lower[:2] - lower[:2], upper[:2] - seen_upper[:2]])
        assert np.all(inward > -0.003) and np.all(inward < 0.015), (seen_lower, seen_upper, lower, upper)
        assert abs(seen_lower[2] - lower[2]) < 0.003
        assert seen.looks == looks + 1
    finally:
        backend.close()
