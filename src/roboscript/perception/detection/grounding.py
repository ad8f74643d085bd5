"""2D grounding: which boxes in one camera image show the things a program asked for.

A grounder takes a frame and a list of phrases ("apple", "white mug", "footed_bowl") and returns labelled boxes.
:class:`SegmentationGrounder` reads them off the simulator's segmentation: the ground-truth 2D boxes of the
ablations, with optional noise, dropout and label confusion for studies of how detection errors propagate.
Open-vocabulary detectors live in :mod:`roboscript.perception.detection.detectors`.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from roboscript.robot_io import CameraFrame


@dataclass(frozen=True)
class Detection2D:
    """A labelled box in one image: ``box`` is ``(x0, y0, x1, y1)`` in pixels, ``x1``/``y1`` exclusive.
    ``source``: the entity the box was drawn around, where that is known (ground-truth boxes; for evaluation),
    else -1."""

    label: str
    box: tuple[int, int, int, int]
    score: float = 1.0
    source: int = -1

    def __post_init__(self) -> None:
        x0, y0, x1, y1 = self.box
        if not (x1 > x0 and y1 > y0):
            raise ValueError(f"a detection box needs x1 > x0 and y1 > y0, got {self.box}")


def image_box_iou(a: tuple[int, int, int, int], b: tuple[int, int, int, int]) -> float:
    """Intersection over union of two image boxes ``(x0, y0, x1, y1)``."""
    ix = max(0, min(a[2], b[2]) - max(a[0], b[0]))
    iy = max(0, min(a[3], b[3]) - max(a[1], b[1]))
    inter = ix * iy
    union = (a[2] - a[0]) * (a[3] - a[1]) + (b[2] - b[0]) * (b[3] - b[1]) - inter
    return inter / union if union else 0.0


class Grounder(ABC):
    """Finds the things named by ``phrases`` in one frame."""

    reads_segmentation = False  # whether detect reads the frames' segmentation images (else they need not be made)

    @abstractmethod
    def detect(self, frame: CameraFrame, phrases: Sequence[str]) -> list[Detection2D]:
        """Boxes labelled with the phrase they show, at most one label per box."""

    def account(self, phrase: str) -> str:
        """What the grounder can say of a phrase it found nowhere in its last frames (empty: nothing more than
        what the boxes show)."""
        return ""


def normalize_phrase(phrase: str) -> str:
    """``"White Mug"``, ``"white_mug"`` and ``" white  mug "`` all become ``"white mug"``."""
    return " ".join(phrase.replace("_", " ").lower().split())


def entity_phrases(entity: SegmentLabel) -> set[str]:
    """What a person may call an object: its name, its category, and its colour with the category."""
    phrases = {normalize_phrase(entity.name)}
    if entity.category:
        phrases.add(normalize_phrase(entity.category))
        if entity.color:
            phrases.add(normalize_phrase(f"{entity.color} {entity.category}"))
    return phrases


class SegmentLabel(Protocol):
    """What a segmentation label stands for: the world's entities in simulation, a segmentation node's labels on a
    robot. ``kind``: ``object``, ``furniture``, ``part`` (and ``table``, ``robot``, which no phrase names)."""

    @property
    def index(self) -> int: ...

    @property
    def name(self) -> str: ...

    @property
    def kind(self) -> str: ...

    @property
    def category(self) -> str: ...

    @property
    def color(self) -> str: ...


@dataclass(frozen=True)
class GroundingNoise:
    """Errors injected into ground-truth boxes: ``box_jitter`` moves each edge by up to this fraction of the box's
    size; ``dropout`` is the chance a box is missed; ``confusion`` the chance its label is swapped for another
    phrase asked for."""

    box_jitter: float = 0.0
    dropout: float = 0.0
    confusion: float = 0.0

    def __post_init__(self) -> None:
        for name in ("box_jitter", "dropout", "confusion"):
            value = getattr(self, name)
            if not 0.0 <= value <= 1.0:
                raise ValueError(f"GroundingNoise.{name} must be between 0 and 1, got {value}")


class SegmentationGrounder(Grounder):
    """Boxes around the pixels a segmentation image gives each object that a phrase names (the simulator's, or a
    segmentation node's on a robot).

    ``entities``: what the segmentation's labels stand for; ``min_pixels``: smaller glimpses are not reported (a
    detector would miss them too).
    """

    reads_segmentation = True

    def __init__(
        self,
        entities: Sequence[SegmentLabel],
        min_pixels: int = 40,
        noise: GroundingNoise | None = None,
        seed: int = 0,
    ):
        # Furniture and its parts (fronts, handles) too: they answer to their full names only.
        self.entities = [e for e in entities if e.kind in ("object", "furniture", "part")]
        self.min_pixels = min_pixels
        self.noise = noise or GroundingNoise()
        self._rng = np.random.default_rng(seed)

    def detect(self, frame: CameraFrame, phrases: Sequence[str]) -> list[Detection2D]:
        if frame.segmentation is None:
            raise ValueError(f"frame {frame.name!r} has no segmentation; the segmentation grounder needs it")
        wanted = [normalize_phrase(p) for p in phrases]
        seg = frame.segmentation
        present = np.unique(seg)
        out = []
        for entity in self.entities:
            # Furniture answers to its full name only: asking for "handle" should not put handles among the objects.
            names = entity_phrases(entity) if entity.kind == "object" else {normalize_phrase(entity.name)}
            label = next((p for p in wanted if p in names), None)
            if label is None or entity.index not in present:
                continue
            rows, cols = np.nonzero(seg == entity.index)
            if rows.size < self.min_pixels:
                continue
            box = (int(cols.min()), int(rows.min()), int(cols.max()) + 1, int(rows.max()) + 1)
            detection = self._perturb(Detection2D(label, box, 1.0, entity.index), wanted, seg.shape)
            if detection is not None:
                out.append(detection)
        return out

    def _perturb(self, detection: Detection2D, wanted: list[str], shape: tuple[int, int]) -> Detection2D | None:
        noise = self.noise
        if noise.dropout and self._rng.random() < noise.dropout:
            return None
        label, box = detection.label, detection.box
        if noise.confusion and len(set(wanted)) > 1 and self._rng.random() < noise.confusion:
            label = str(self._rng.choice(sorted(set(wanted) - {label})))
        if noise.box_jitter:
            x0, y0, x1, y1 = box
            w, h = x1 - x0, y1 - y0
            dx = self._rng.uniform(-noise.box_jitter, noise.box_jitter, 2) * w
            dy = self._rng.uniform(-noise.box_jitter, noise.box_jitter, 2) * h
            x0, x1 = int(np.clip(x0 + dx[0], 0, shape[1] - 1)), int(np.clip(x1 + dx[1], 1, shape[1]))
            y0, y1 = int(np.clip(y0 + dy[0], 0, shape[0] - 1)), int(np.clip(y1 + dy[1], 1, shape[0]))
            if x1 <= x0 or y1 <= y0:
                return None
            box = (x0, y0, x1, y1)
        return Detection2D(label, box, detection.score, detection.source)
