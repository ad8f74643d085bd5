"""The detector the project trains itself (``roboscript train-detector``): 2D boxes of the things phrases name, from
one RGB-D frame, with nothing from the simulator.

The frame's things and their classes come from :mod:`roboscript.perception.detection.things`. A phrase labels the things
whose class holds a type it names, the most specifically named ones first
(:mod:`roboscript.perception.detection.phrases`); furniture and handles are split into the carcass and its rows' parts
by geometry (:mod:`roboscript.perception.detection.furniture_parts`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING

import numpy as np

from roboscript.perception.detection.detector_model import OTHER, DetectorModel, load_detector_model
from roboscript.perception.detection.furniture_parts import FurnitureRows, split_furniture
from roboscript.perception.detection.grounding import Detection2D, Grounder, normalize_phrase
from roboscript.perception.detection.phrases import PhraseMatch, match_phrase
from roboscript.perception.detection.segment_merging import union
from roboscript.perception.detection.things import FrameThings, ThingFinder
from roboscript.robot_io import CameraFrame

if TYPE_CHECKING:  # a scene's description is a world file's; perception reads it, and never the simulator
    from roboscript.sim.world_file import WorldSpec

MIN_PIXELS = 40  # full-resolution pixels a thing must cover to be reported (as the ground-truth boxes' minimum)
MIN_SCORE = 0.3  # classifier probability below which a thing is not reported as an object


class TrainedDetector(Grounder):
    """The trained detector: ``model`` (the packaged one by default); ``furniture``: the furniture the scene's
    description lists, with its rows; ``described``: the description's object names and their types (a name such
    as ``white_plate`` then means the type it was given, not every white plate)."""

    def __init__(
        self,
        model: DetectorModel | None = None,
        furniture: Sequence[FurnitureRows] = (),
        described: Mapping[str, str] | None = None,
    ):
        self.model = model or load_detector_model()
        self.furniture = list(furniture)
        self.described = dict(described or {})
        # The types the scene holds, where a description says (what a thing may be: ThingFinder.find).
        self._present = set(self.described.values()) if self.described else None
        self.finder = ThingFinder(self.model)
        self.last: dict[str, FrameThings] = {}  # the last frame of each camera, as seen (for "not found" messages)

    @classmethod
    def for_scene(cls, scene: WorldSpec | None, model: DetectorModel | None = None) -> TrainedDetector:
        """The detector for a scene a description (a world file) describes: its furniture's rows and its objects'
        types; without one, phrases are read in the object library's words alone and no furniture is known."""
        if scene is None:
            return cls(model)
        furniture = [FurnitureRows(c.name, tuple(r.kind for r in c.rows)) for c in scene.cabinets]
        return cls(model, furniture, {o.name: o.type.name for o in scene.objects})

    def things(self, frame: CameraFrame) -> FrameThings:
        """The things ``frame`` shows and their classes (kept as the camera's last)."""
        self.last[frame.name] = found = self.finder.find(frame, self._present)
        return found

    # --- grounding ---

    def detect(self, frame: CameraFrame, phrases: Sequence[str]) -> list[Detection2D]:
        wanted = list(dict.fromkeys(normalize_phrase(p) for p in phrases))
        if not wanted:
            return []
        seen = self.things(frame)
        return self._objects(seen, wanted) + self._furniture(seen, wanted)

    def _objects(self, seen: FrameThings, wanted: list[str]) -> list[Detection2D]:
        matches = {p: m for p in wanted if (m := match_phrase(p, self.described)) is not None}
        # Per phrase, the things it names most specifically in this frame.
        candidates: dict[int, list[tuple[int, int, str]]] = {}
        for order, (phrase, match) in enumerate(matches.items()):
            named = [(k, self._specificity(match, int(seen.classes[k]))) for k in range(len(seen.classes))]
            named = [(k, s) for k, s in named if s > 0 and seen.scores[k] >= MIN_SCORE]
            best = max((s for _, s in named), default=0)
            for k, s in named:
                if s == best:
                    candidates.setdefault(k, []).append((s, -order, phrase))
        labels = {k: max(options)[2] for k, options in candidates.items()}
        # A thing a phrase names less specifically that borders one it labels is a part of it the merge left apart
        # (the lower half of a two-coloured mug, taken for a white one); things it labels twice side by side, too.
        pairs = [
            (a, b)
            for a, b in seen.adjacent.tolist()
            for x, y in ((a, b), (b, a))
            if x in labels and self._part_of(labels, matches, seen, x, y)
        ]
        groups = union(len(seen.classes), np.array(pairs)) if pairs else np.arange(len(seen.classes))
        out = []
        for group in {groups[k] for k in labels}:
            members = np.flatnonzero(groups == group).tolist()
            pixels = np.concatenate([seen.pixels(k) for k in members])
            if pixels.size * seen.frame.stride**2 < MIN_PIXELS:
                continue
            labelled = [k for k in members if k in labels]
            best = max(labelled, key=lambda k: max(candidates[k]))
            out.append(Detection2D(labels[best], seen.box(pixels), float(seen.scores[best])))
        return out

    def _part_of(self, labels: dict[int, str], matches: dict, seen: FrameThings, labelled: int, other: int) -> bool:
        """Whether ``other``, which borders the labelled thing ``labelled``, is part of what that label names."""
        if other in labels:
            return labels[other] == labels[labelled]
        return self._specificity(matches[labels[labelled]], int(seen.classes[other])) > 0

    def _specificity(self, match: PhraseMatch, class_index: int) -> int:
        return max((match.specificity.get(t, 0) for t in self.finder.types[class_index]), default=0)

    def _furniture(self, seen: FrameThings, wanted: list[str]) -> list[Detection2D]:
        asked = [f for f in self.furniture if normalize_phrase(f.name) in wanted]
        if not asked:
            return []
        flat = seen.things.ravel()
        thing_class = np.where(flat >= 0, seen.classes[np.maximum(flat, 0)], self.finder.other_class)
        body = np.flatnonzero((flat >= 0) & (thing_class == self.finder.furniture_class))
        handles = [seen.pixels(k) for k in np.flatnonzero(seen.classes == self.finder.handle_class)]
        points = seen.frame.points.reshape(-1, 3)
        normals = seen.frame.normals.reshape(-1, 3)
        # One piece of furniture is told apart from the rest: the first the description lists.
        parts = split_furniture(
            points[body], normals[body], [points[h] for h in handles], seen.segmentation.table_height, asked[0]
        )
        out = []
        for name, members in parts.items():
            label = normalize_phrase(name)
            if label not in wanted:
                continue
            pixels = np.concatenate([handles[j] for j in members]) if ".handle_" in name else body[members]
            if pixels.size * seen.frame.stride**2 >= MIN_PIXELS:
                out.append(Detection2D(label, seen.box(pixels), 1.0))
        return out

    def account(self, phrase: str) -> str:
        """Whether the phrase names anything the detector knows, and what its last frames showed."""
        counts: dict[str, int] = {}
        for seen in self.last.values():
            for k, score in zip(seen.classes, seen.scores, strict=True):
                name = self.model.classes[k]
                if name != OTHER and score >= MIN_SCORE:
                    counts[name] = counts.get(name, 0) + 1
        things = ", ".join(
            f"{name.replace('+', ' or ')} in {n} view{'s' * (n > 1)}" for name, n in sorted(counts.items())
        )
        saw = f"the detector saw {things or 'nothing'}"
        if match_phrase(phrase, self.described) is None and normalize_phrase(phrase) not in self._furniture_phrases():
            return (
                f"{phrase!r} names nothing the detector knows (it knows the object library's types, categories and "
                f"colours, e.g. 'white_ceramic_plate', 'plate', 'white plate', 'fruit'); {saw}"
            )
        return saw

    def _furniture_phrases(self) -> set[str]:
        names = {n for f in self.furniture for n in (f.name, *(x for pair in f.part_names() for x in pair))}
        return {normalize_phrase(n) for n in names}
