"""A planning scene changed for the length of a block, for questions about the hand as it will be rather than as
it is: once it has let go (what it held collides with nothing, its fingers spread to their full width), or while
it carries something past others (what it holds keeps a wider berth)."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

import numpy as np

from roboscript.planning.scene import PlanningScene


@contextlib.contextmanager
def ignoring_held(scene: PlanningScene) -> Iterator[None]:
    """Within this block, what the gripper holds collides with nothing: for questions about the hand once it
    has let go (can it leave the place where it puts something down?)."""
    geoms = np.isin(scene.model.geom_bodyid, scene.held_bodies) & scene.colliding_geoms
    saved = scene.model.geom_contype[geoms].copy(), scene.model.geom_conaffinity[geoms].copy()
    scene.model.geom_contype[geoms], scene.model.geom_conaffinity[geoms] = 0, 0
    try:
        yield
    finally:
        scene.model.geom_contype[geoms], scene.model.geom_conaffinity[geoms] = saved


@contextlib.contextmanager
def fingers_open(scene: PlanningScene) -> Iterator[None]:
    """Within this block, the gripper is fully open (every joint of its linkage at the open position, the
    model's reference elsewhere): for questions about the hand once it lets go, when the fingers spread to
    their full width whatever stands beside them."""
    saved = scene.data.qpos[scene.finger_qpos].copy()
    scene.data.qpos[scene.finger_qpos] = scene.finger_open
    try:
        yield
    finally:
        scene.data.qpos[scene.finger_qpos] = saved


@contextlib.contextmanager
def held_clearance(scene: PlanningScene, clearance: float) -> Iterator[None]:
    """Within this block, what the gripper holds counts as colliding closer than ``clearance`` to anything
    (rather than the padding): for transfers, where a held object swinging a little must not graze what it
    passes."""
    geoms = np.isin(scene.model.geom_bodyid, scene.held_bodies) & scene.colliding_geoms
    saved = scene.model.geom_margin[geoms].copy()
    scene.model.geom_margin[geoms] = np.maximum(saved, clearance)
    scene.sync_body_margins()
    try:
        yield
    finally:
        scene.model.geom_margin[geoms] = saved
        scene.sync_body_margins()
