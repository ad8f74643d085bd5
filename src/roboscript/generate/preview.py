"""A generated world built in simulation: whether it settles where its file puts things, and its view from above."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.backends.mujoco_snapshot import top_view
from roboscript.sim.world_file import WorldSpec

SETTLE_S = 1.0
SETTLED_WITHIN = 0.02  # metres an object may move while the world settles
TOP_VIEW = (640, 480)


@dataclass(frozen=True)
class Settled:
    """How far each object moved (metres) in the first simulated second, and the lowest it ended (its box's
    bottom, metres above the floor)."""

    moved: dict[str, float]
    lowest: float

    @property
    def ok(self) -> bool:
        return max(self.moved.values(), default=0.0) <= SETTLED_WITHIN

    def worst(self) -> tuple[str, float]:
        return max(self.moved.items(), key=lambda kv: kv[1], default=("", 0.0))


def settle(world: WorldSpec, image: str | Path | None = None) -> Settled:
    """Builds ``world``, lets it settle for a simulated second and measures how far things moved; with
    ``image``, writes its top view there (PNG)."""
    with MujocoBackend(world, settle=0.0) as backend:
        gt = backend.ground_truth
        names = world.object_names()
        before = {n: gt.box(n).center.copy() for n in names}
        backend.simulator.settle(SETTLE_S)
        moved = {n: round(float(np.linalg.norm(gt.box(n).center - before[n])), 4) for n in names}
        lowest = min((float(gt.box(n).lower[2]) for n in names), default=0.0)
        if image is not None:
            Image.fromarray(top_view(backend, *TOP_VIEW, distance=2.2)).save(image)
    return Settled(moved, lowest)
