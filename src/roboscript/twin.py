"""The simulated twin of a scene as a robot perceives it: what a program is tried on before it reaches the robot.

The twin is a world like any other (a :class:`WorldSpec`), built from three sources:

- the scene's description (the world file the robot's run names): its furniture, cameras and the objects' kinds;
- perception: the table's top at the height the cameras measured, and every object where they saw it (the centre
  and turn of its footprint);
- the robot's joint states: the twin's arm starts where the real one stands.

An object the description names keeps its modelled shape (a mug stays a mug, so that grasps and placements on the
twin are those the robot will try); one the description does not name becomes the box perception saw. Objects seen
off the table (on another object, inside a drawer) are left out and listed, as their support is not known to the
twin; a program that uses one then fails on the twin, which is the safe way round.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from roboscript.names import TABLE
from roboscript.objects import ObjectType
from roboscript.objects import designs as shapes
from roboscript.perception.base import Perception
from roboscript.sim.world_file import ObjectPlacement, Randomization, WorldSpec

ON_TABLE = 0.03  # metres: an object whose lowest seen point is this close to the table's top stands on it
BOX_DENSITY = 300.0  # kg/m^3: what a box of unknown contents is given (a cardboard box of groceries)


@dataclass(frozen=True)
class Twin:
    """A twin's world, and what of the perceived scene it could not hold (name: why)."""

    world: WorldSpec
    left_out: dict[str, str]

    def summary(self) -> str:
        """One line: what the twin holds and what it left out."""
        text = (
            f"twin of the perceived scene: table top at {self.world.table.height:.3f} m, "
            f"{len(self.world.objects)} objects ({', '.join(self.world.object_names()) or 'none'})"
        )
        if self.left_out:
            text += "; left out: " + "; ".join(f"{n} ({why})" for n, why in self.left_out.items())
        return text


def perceived_twin(scene: WorldSpec, perception: Perception) -> Twin:
    """The twin of what ``perception`` sees now, in the frame of ``scene`` (the description the run was given).

    Looks once with every camera for everything the perception knows to look for."""
    perception.detect(None)
    table_top = float(perception.box(TABLE).upper[2])
    if not math.isfinite(table_top):
        raise ValueError("the cameras did not see the table's top, so the twin cannot be placed: is the table in view?")
    described = {o.name: o for o in scene.objects}
    placed, left_out = [], {}
    for name in perception.objects():
        try:
            box = perception.box(name)
            center, yaw, half = perception.footprint(name)
        except (KeyError, ValueError) as exc:
            left_out[name] = f"not seen: {exc}"
            continue
        if box.lower[2] - table_top > ON_TABLE:
            left_out[name] = f"seen {box.lower[2] - table_top:.2f} m above the table, not standing on it"
            continue
        height = max(float(box.upper[2]) - table_top, 0.005)
        kind = described[name].type if name in described else _box_type(name, half, height)
        placed.append(_placement(name, kind, np.asarray(center, dtype=float), float(yaw), np.asarray(half)))
    table = replace(scene.table, height=table_top)
    world = replace(
        scene,
        name=f"{scene.name}_twin",
        source=f"twin of {scene.source}",
        table=table,
        objects=tuple(placed),
        randomization=Randomization(),
    )
    return Twin(world, left_out)


def _box_type(name: str, half: np.ndarray, height: float) -> ObjectType:
    """An object the description does not name: the box perception saw."""
    size = (2 * float(half[0]), 2 * float(half[1]), height)
    return ObjectType(
        name=f"seen_{name}",
        category=name,
        color="gray",
        parts=shapes.box(*size),
        density=BOX_DENSITY,
        description=f"what the cameras saw of {name}: a {size[0]:.2f} x {size[1]:.2f} x {size[2]:.2f} m box",
        shape="box",
    )


def _placement(name: str, kind: ObjectType, center: np.ndarray, yaw: float, half: np.ndarray) -> ObjectPlacement:
    """``kind`` placed so that its footprint's centre is at ``center``, turned so that its longer side lies along
    the seen footprint's longer side (a footprint's turn is known up to a quarter turn)."""
    lower, upper = kind.bounds
    extent = upper[:2] - lower[:2]
    if (extent[0] >= extent[1]) != (half[0] >= half[1]):
        yaw += math.pi / 2
    offset = (lower[:2] + upper[:2]) / 2
    c, s = math.cos(yaw), math.sin(yaw)
    origin = center[:2] - np.array([c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]])
    return ObjectPlacement(name, kind, (float(origin[0]), float(origin[1])), yaw)
