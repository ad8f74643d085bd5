"""How well perception saw a simulated world: 3D box IoU and centre error against ground truth, and how many
cross-view tuples hold boxes of one object only. Used by the tests and ``benchmarks/perception.py``."""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Box3D
from roboscript.perception.detection.grounding import Detection2D
from roboscript.perception.reconstruction.instances import Instance3D
from roboscript.perception.reconstruction.matching import MatchedObject
from roboscript.sim.ground_truth import GroundTruth


def box_iou(a: Box3D, b: Box3D) -> float:
    """Intersection over union of two axis-aligned boxes."""
    return a.iou(b)


def source_of(boxes: Sequence[int], detections: Sequence[Sequence[Detection2D]]) -> int:
    """The entity most of an object's boxes were drawn around (-1 if unknown)."""
    sources = Counter(detections[v][i].source for v, i in enumerate(boxes) if i != -1)
    return sources.most_common(1)[0][0] if sources else -1


def tuple_is_correct(obj: MatchedObject, detections: Sequence[Sequence[Detection2D]]) -> bool:
    """All boxes of the tuple show the same entity."""
    sources = {detections[v][i].source for v, i in enumerate(obj.boxes) if i != -1}
    return len(sources) == 1 and -1 not in sources


@dataclass(frozen=True)
class ObjectScore:
    name: str
    iou: float
    center_error: float  # metres


def score_instances(
    instances: Sequence[Instance3D], detections: Sequence[Sequence[Detection2D]], gt: GroundTruth
) -> list[ObjectScore]:
    """IoU and centre error of each instance's box against its entity's ground-truth box."""
    names = {e.index: e.name for e in gt.world.entities}
    scores = []
    for instance in instances:
        source = source_of(instance.boxes, detections)
        if source not in names:
            continue
        truth = gt.box(names[source])
        error = float(np.linalg.norm(instance.box.center - truth.center))
        scores.append(ObjectScore(names[source], box_iou(instance.box, truth), error))
    return scores
