"""How well the trained detector finds things in 2D: per object and view, against the boxes of the simulator's
segmentation.

In each view every object that shows at least 40 pixels (as the ground-truth boxes' grounder reports them) is to be
found. The detector is asked for every object by its name in the world (as ``detect_objects()`` asks for the task's
vocabulary) and for the furniture and its parts, knowing what a description says: the objects' types and the
furniture's rows. A detection is right when its label names the object and its box overlaps the object's box by an
IoU of at least 0.5; precision is the share of detections that are right, recall the share of objects found.
Furniture parts are scored the same way, apart.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field

from roboscript.detector_training.scenes import LabelledView
from roboscript.perception.detection.detector_model import DetectorModel
from roboscript.perception.detection.grounding import Detection2D, SegmentationGrounder, image_box_iou, normalize_phrase
from roboscript.perception.detection.trained_detector import TrainedDetector
from roboscript.perception.points import without_pixels

IOU = 0.5


@dataclass
class Tally:
    """Detections made and right, objects to find and found; what was missed or mistaken, by name."""

    detections: int = 0
    right: int = 0
    objects: int = 0
    found: int = 0
    missed: Counter = field(default_factory=Counter)
    wrong: Counter = field(default_factory=Counter)

    @property
    def precision(self) -> float:
        return self.right / self.detections if self.detections else 1.0

    @property
    def recall(self) -> float:
        return self.found / self.objects if self.objects else 1.0

    def add(self, truth: dict[str, tuple[int, int, int, int]], detections: list[Detection2D], key) -> None:
        self.objects += len(truth)
        self.detections += len(detections)
        matched = set()
        for d in detections:
            box = truth.get(d.label)
            if box is not None and d.label not in matched and image_box_iou(box, d.box) >= IOU:
                matched.add(d.label)
                self.right += 1
            else:
                self.wrong[key(d.label)] += 1
        self.found += len(matched)
        self.missed.update(key(n) for n in truth if n not in matched)

    def line(self) -> str:
        return (
            f"precision {self.precision:.3f} ({self.right}/{self.detections}), "
            f"recall {self.recall:.3f} ({self.found}/{self.objects})"
        )


@dataclass
class DetectionScores:
    """Objects' and furniture parts' tallies over the views scored."""

    objects: Tally = field(default_factory=Tally)
    parts: Tally = field(default_factory=Tally)
    views: int = 0

    def as_dict(self) -> dict:
        return {
            "views": self.views,
            "objects": {"precision": self.objects.precision, "recall": self.objects.recall,
                        "detections": self.objects.detections, "instances": self.objects.objects},
            "parts": {"precision": self.parts.precision, "recall": self.parts.recall,
                      "detections": self.parts.detections, "instances": self.parts.objects},
        }  # fmt: skip


def score_views(model: DetectorModel, views: Iterable[LabelledView]) -> DetectionScores:
    """The detector's scores over ``views`` (each with its robot's pixels zeroed, as the pipeline gives them)."""
    scores = DetectionScores()
    detectors: dict[str, TrainedDetector] = {}
    for view in views:
        spec = view.spec
        if spec.name not in detectors:
            detectors[spec.name] = TrainedDetector.for_scene(spec, model)
        detector = detectors[spec.name]
        objects = {normalize_phrase(o.name): o.type.name for o in spec.objects}
        parts = [normalize_phrase(n) for c in spec.cabinets for n in (c.name, *c.part_names())]
        truth = SegmentationGrounder(list(view.labels.values())).detect(view.frame, [*objects, *parts])
        frame = without_pixels(view.frame, view.robot_mask)
        found = detector.detect(frame, [*objects, *parts])
        scores.objects.add(
            {d.label: d.box for d in truth if d.label in objects},
            [d for d in found if d.label in objects],
            objects.__getitem__,
        )
        scores.parts.add(
            {d.label: d.box for d in truth if d.label not in objects},
            [d for d in found if d.label not in objects],
            lambda name: name.split(".")[-1].rstrip(" 0123456789"),
        )
        scores.views += 1
    return scores

