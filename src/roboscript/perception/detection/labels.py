"""Labels from a description, not from sight: what furniture has which parts, which handle moves which part and how
(it slides or turns), and what a segmentation image's labels stand for.

On a real robot these come from a description of the scene (a world file naming the cabinet and its rows) and from
the segmentation node's label list; everything geometric (boxes, points, joints' axes) is still perceived.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from roboscript.names import TABLE, kind_of
from roboscript.objects import object_types
from roboscript.perception.base import ArticulationJoint

ROBOT_LABEL = "robot"


class PartLabels(Protocol):
    """What the camera pipeline asks of its labels: furniture and parts by name, and each one's joints (which part
    moves, and how); :class:`FurnitureLabels` from a description, ground truth in simulation."""

    def furniture(self) -> list[str]: ...

    def joints(self, name: str) -> list[ArticulationJoint]: ...


@dataclass(frozen=True)
class PartLabel:
    """A moving part of furniture: ``joint`` is ``prismatic`` (a drawer) or ``revolute`` (a door); ``handle`` the
    handle on it."""

    part: str
    joint: str
    handle: str


class FurnitureLabels:
    """What the labels say of furniture: the names of each piece and its parts, and which part each handle moves.

    Answers :meth:`furniture` and :meth:`joints` as :class:`~roboscript.perception.pipeline.PipelinePerception` asks
    its labels; the joints' geometry is unknown here (NaN) and is estimated from the points seen."""

    def __init__(self, furniture: Iterable[str] = (), parts: Iterable[PartLabel] = ()):
        self._furniture = list(furniture)
        self._parts = list(parts)
        self._by_name = {p.part: p for p in self._parts} | {p.handle: p for p in self._parts}

    def furniture(self) -> list[str]:
        return [*self._furniture, *(p.part for p in self._parts), *(p.handle for p in self._parts)]

    def joints(self, name: str) -> list[ArticulationJoint]:
        if name in self._furniture:
            labels = [p for p in self._parts if p.part.startswith(name + ".")]
        elif name in self._by_name:
            labels = [self._by_name[name]]
        else:
            return []
        nan = np.full(3, math.nan)
        return [ArticulationJoint(p.part, p.joint, nan, nan, math.nan, math.nan, math.nan) for p in labels]


@dataclass(frozen=True)
class SegmentLabel:
    """What one label of a segmentation image stands for (see
    :class:`~roboscript.perception.detection.grounding.SegmentLabel`, the protocol this fulfils)."""

    index: int
    name: str
    kind: str
    category: str = ""
    color: str = ""


def segment_labels(labels: Mapping[int, str], furniture: Sequence[str] = ()) -> list[SegmentLabel]:
    """The labels a segmentation node publishes (index -> name), with their kinds, and for objects the category
    and colour the object library gives the name (or its type, for ``mug_1``)."""
    library = object_types()
    out = []
    for index, name in sorted(labels.items()):
        if name in (TABLE, ROBOT_LABEL):
            out.append(SegmentLabel(index, name, name))
        elif name in furniture or kind_of(name) != "other":
            out.append(SegmentLabel(index, name, "part" if "." in name else "furniture"))
        else:
            base = name.rstrip("0123456789").rstrip("_")
            kind = library.get(name) or library.get(base)
            out.append(SegmentLabel(index, name, "object", kind.category if kind else "", kind.color if kind else ""))
    return out
