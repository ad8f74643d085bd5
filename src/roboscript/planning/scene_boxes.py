"""The planning scene as boxes, for people to look at (recordings): each body the arm must avoid, as the world box
around its colliding geoms."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Box3D
from roboscript.planning.scene import PlanningScene

_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)


def obstacle_boxes(scene: PlanningScene) -> dict[str, Box3D]:
    """Body name -> world box of its colliding geoms, for every body but the arm's moving links and what it holds,
    where the scene last placed them."""
    model, data = scene.model, scene.data
    skip = set(int(b) for b in scene.moving_bodies) | set(scene.held_bodies)
    colliding = np.flatnonzero((model.geom_contype | model.geom_conaffinity) > 0)
    corners: dict[int, list[np.ndarray]] = {}
    for g in colliding:
        body = int(model.geom_bodyid[g])
        if body in skip or (body == 0 and model.geom_type[g] == 0):  # the ground plane has no box
            continue
        centre, half = model.geom_aabb[g, :3], model.geom_aabb[g, 3:]
        local = centre + _CORNERS * half
        world = data.geom_xpos[g] + local @ data.geom_xmat[g].reshape(3, 3).T
        corners.setdefault(body, []).append(world)
    return {model.body(b).name or f"body{b}": Box3D.from_points(np.vstack(c)) for b, c in corners.items()}
