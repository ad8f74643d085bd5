"""Telling a cabinet's parts apart by geometry: given which pixels are furniture and which are handles (here from
the simulator's segmentation, the detector's job at run time), every handle goes to its row and every front pixel
to its row's drawer or door, closed or pulled out."""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.perception.detection.furniture_parts import FurnitureRows, row_bands, split_furniture
from roboscript.perception.detection.segments import frame_points, table_height

ROWS = FurnitureRows("cabinet", ("drawer", "drawer", "drawer", "door"))


def _split(backend: MujocoBackend, camera: str):
    frame = backend.capture(camera)
    fp = frame_points(frame)
    truth = frame.segmentation[:: fp.stride, :: fp.stride].ravel()
    names = {e.index: e.name for e in backend.ground_truth.world.entities}
    kinds = {e.index: e.kind for e in backend.ground_truth.world.entities}
    is_body = {i: kinds[i] in ("furniture", "part") and ".handle_" not in names[i] for i in names}
    furniture = np.array([is_body.get(int(t), False) for t in truth])
    furniture &= np.isfinite(fp.points.reshape(-1, 3)).all(axis=1)
    handle_ids = sorted({int(t) for t in truth if ".handle_" in names.get(int(t), "")})
    points, normals = fp.points.reshape(-1, 3), fp.normals.reshape(-1, 3)
    body = np.flatnonzero(furniture)
    handles = [np.flatnonzero(truth == h) for h in handle_ids]
    handles = [h[np.isfinite(points[h]).all(axis=1)] for h in handles]
    parts = split_furniture(points[body], normals[body], [points[h] for h in handles], table_height(fp), ROWS)
    return parts, body, truth, names, handle_ids


@pytest.mark.parametrize(("drawer", "pulled"), [("drawer_1", 0.0), ("drawer_1", 0.2), ("drawer_0", 0.15)])
def test_fronts_and_handles_go_to_their_rows(drawer, pulled):
    """Closed, the second drawer pulled out, and the top drawer pulled out (the top edge of its front, 2 cm below
    the cabinet's top, is no part of the top)."""
    with MujocoBackend("world_5_mug_to_cabinet", robot="panda", settle=0) as backend:
        world = backend.sim_world
        joint = world.model.joint(f"cabinet.{drawer}.joint")
        world.data.qpos[joint.qposadr[0]] = pulled
        mujoco.mj_forward(world.model, world.data)
        parts, body, truth, names, handle_ids = _split(backend, "camera_left")
    for k, handle in enumerate(handle_ids):
        assert parts[names[handle]].tolist() == [k]  # each handle, in its row
    for part in ("cabinet.drawer_0", "cabinet.drawer_1", "cabinet.drawer_2", "cabinet.door_0"):
        mine = truth[body[parts[part]]]
        own = np.mean([names.get(int(t)) == part for t in mine])
        index = next(i for i, n in names.items() if n == part)
        found = np.isin(np.flatnonzero(truth == index), body[parts[part]]).mean()
        assert own > 0.75, (part, own)  # what is given a part is mostly that part (and the frame around it)
        assert found > 0.65, (part, found)  # and most of it is found (less what a pulled drawer keeps inside)
    assert len(parts["cabinet"]) == len(body)  # the carcass stands around its parts


def test_without_a_handle_the_parts_cannot_be_told():
    points = np.random.default_rng(0).uniform([-0.6, 0.4, 0.82], [-0.2, 0.8, 1.3], (500, 3))
    normals = np.tile([1.0, 0.0, 0.0], (500, 1))
    parts = split_furniture(points, normals, [], 0.82, ROWS)
    assert list(parts) == ["cabinet"] and len(parts["cabinet"]) == 500
    assert split_furniture(np.zeros((0, 3)), np.zeros((0, 3)), [], 0.82, ROWS) == {}
    assert ROWS.part_names()[3] == ("cabinet.door_0", "cabinet.handle_3")


def test_each_rows_height_range_follows_its_handles_and_the_panels_between_rows_belong_to_none():
    """Rows 14 cm high with 1.5 cm panels between them (15.5 cm apart), handles seen on the first two rows only:
    the third row is placed below them, and its range stops short of the floor of a drawer pulled out above it
    (the range of the row above it starts 1.5 cm higher)."""
    bands = row_bands({0: 1.24, 1: 1.085}, rows=3, top=1.32, table=0.82)
    centres = [(low + high) / 2 for low, high in bands]
    assert centres == pytest.approx([1.24, 1.085, 0.93], abs=1e-6)
    assert bands[2][1] == pytest.approx(0.93 + 0.92 * 0.155 / 2 + 0.005, abs=1e-6)
    assert bands[2][1] < 1.01  # the floor of the drawer above, 1 cm over the panel, is no part of the door
    alone = row_bands({1: 1.085}, rows=3, top=1.32, table=0.82)  # one handle: the rest spaced by the height
    assert [round((a + b) / 2, 3) for a, b in alone] == [round(1.085 + 0.5 / 3, 3), 1.085, round(1.085 - 0.5 / 3, 3)]
