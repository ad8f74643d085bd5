"""The detector the project trains itself (``roboscript train-detector``): 2D boxes of the things phrases name, from
one RGB-D frame, with nothing from the simulator.

Each frame is cut into pieces (:mod:`roboscript.perception.segments`), the pieces are joined into things by the
learned merging network (:mod:`roboscript.perception.segment_merging`), and each thing is classified by the learned
classifier into one of the object library's look-alike classes, furniture, a handle, or other
(:mod:`roboscript.perception.detector_model`). A phrase labels the things whose class holds a type it names, the
most specifically named ones first (:mod:`roboscript.perception.phrases`); furniture and handles are split into
the carcass and its rows' parts by geometry (:mod:`roboscript.perception.furniture_parts`).

Pixels whose depth is 0 are not looked at: the pipeline zeroes the robot's own (its self-filter's mask) before it
asks.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from scipy.spatial import cKDTree

from roboscript.objects import object_types
from roboscript.perception.detector_model import FURNITURE, HANDLE, OTHER, DetectorModel, load_detector_model
from roboscript.perception.furniture_parts import FurnitureRows, split_furniture
from roboscript.perception.grounding import Detection2D, Grounder, normalize_phrase
from roboscript.perception.phrases import PhraseMatch, match_phrase
from roboscript.perception.segment_features import EXTENT, RISE, features_of_pixels
from roboscript.perception.segment_merging import describe_pieces, merge, union
from roboscript.perception.segments import FramePoints, Segmentation, frame_points, segment
from roboscript.robot_io import CameraFrame

if TYPE_CHECKING:  # a scene's description is a world file's; perception reads it, and never the simulator
    from roboscript.sim.world_file import WorldSpec

MIN_PIXELS = 40  # full-resolution pixels a thing must cover to be reported (as the ground-truth boxes' minimum)
MIN_SCORE = 0.3  # classifier probability below which a thing is not reported as an object
BOX_PADDING = 1  # working pixels a box is grown by on every side
TOUCHING = 0.012  # metres: things of one class closer than this are one thing
SPAN_SLACK = 0.01  # metres beyond its class's widest footprint that pieces of one thing may spread over
SIZE_SLACK = (1.2, 0.03)  # a thing may measure this much (times, plus metres) more than its class's largest
SAMPLE = 200  # points of each thing compared when measuring how close two are


def _diameter(points: np.ndarray) -> float:
    """The largest horizontal distance between two of ``points``."""
    xy = points[:, :2]
    return float(np.sqrt(((xy[:, None, :] - xy[None, :, :]) ** 2).sum(axis=-1).max()))


def _sample(points: np.ndarray) -> np.ndarray:
    """At most :data:`SAMPLE` of the finite ``points``, evenly spread through the array."""
    points = points[np.isfinite(points).all(axis=1)]
    if len(points) > SAMPLE:
        points = points[np.linspace(0, len(points) - 1, SAMPLE).astype(int)]
    return points


@dataclass
class FrameThings:
    """What one frame shows, before any phrase: the working-resolution image of each thing's index (-1: none),
    each thing's class index and probability."""

    frame: FramePoints
    segmentation: Segmentation
    things: np.ndarray  # (h, w) int
    classes: np.ndarray  # (n,) int
    scores: np.ndarray  # (n,)

    def pixels(self, thing: int) -> np.ndarray:
        return np.flatnonzero(self.things.ravel() == thing)

    def box(self, pixels: np.ndarray) -> tuple[int, int, int, int]:
        """The full-resolution box ``(x0, y0, x1, y1)`` of working pixels (flat indices), grown by
        :data:`BOX_PADDING` working pixels: a thing's outermost pixels, where the depth steps off it, and its
        lowest few millimetres, next to the table, are cut off its piece, and the box should hold them."""
        h, w = self.things.shape
        s = self.frame.stride
        rows, cols = pixels // w, pixels % w
        pad = BOX_PADDING
        return (
            max(int(cols.min()) - pad, 0) * s,
            max(int(rows.min()) - pad, 0) * s,
            min(int(cols.max()) + 1 + pad, w) * s,
            min(int(rows.max()) + 1 + pad, h) * s,
        )


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
        self._types = [frozenset(self.model.types_of(k)) for k in range(len(self.model.classes))]
        library = object_types()
        # The widest a thing of each class is across, seen from above (the diagonal of its footprint).
        self._span = [
            max((float(np.hypot(*library[t].size[:2])) for t in types), default=0.0) for types in self._types
        ]
        # The most a thing of each class can measure in any direction, however it lies (its box's diagonal), with
        # room for the depth images' noise; what measures more is of another class.
        largest = [max((float(np.linalg.norm(library[t].size)) for t in ts), default=np.inf) for ts in self._types]
        self._largest = np.array(largest) * SIZE_SLACK[0] + SIZE_SLACK[1]
        self._furniture_class = self.model.classes.index(FURNITURE)
        self._handle_class = self.model.classes.index(HANDLE)
        self._other_class = self.model.classes.index(OTHER)
        self.last: dict[str, FrameThings] = {}  # the last frame of each camera, as seen (for "not found" messages)

    @classmethod
    def for_scene(cls, scene: WorldSpec | None, model: DetectorModel | None = None) -> TrainedDetector:
        """The detector for a scene a description (a world file) describes: its furniture's rows and its objects'
        types; without one, phrases are read in the object library's words alone and no furniture is known."""
        if scene is None:
            return cls(model)
        furniture = [FurnitureRows(c.name, tuple(r.kind for r in c.rows)) for c in scene.cabinets]
        return cls(model, furniture, {o.name: o.type.name for o in scene.objects})

    # --- seeing ---

    def things(self, frame: CameraFrame) -> FrameThings:
        """The things ``frame`` shows and their classes."""
        fp = frame_points(frame)
        seg = segment(fp)
        pieces = describe_pieces(seg)
        piece_thing = merge(pieces, self.model.merger)
        things = np.full(seg.labels.shape, -1)
        placed = seg.labels >= 0
        things[placed] = piece_thing[seg.labels[placed]]
        count = int(piece_thing.max()) + 1 if piece_thing.size else 0
        classes, scores = self._classify(fp, seg, things, count)
        # Two things of one object class that touch, in the image or in space, are one thing the merge left in two
        # (a bowl's inside and outside, a mug's handle seen through its gap).
        if count:
            pairs = self._same_class_neighbours(fp, pieces, piece_thing, things, classes)
            if len(pairs):
                joined = union(count, pairs)
                piece_thing = joined[piece_thing]
                things[placed] = piece_thing[seg.labels[placed]]
                count = int(joined.max()) + 1
                classes, scores = self._classify(fp, seg, things, count)
        found = FrameThings(fp, seg, things, classes, scores)
        self.last[frame.name] = found
        return found

    def _object_classes(self) -> np.ndarray:
        return np.array([k for k, t in enumerate(self._types) if t])

    def _same_class_neighbours(
        self, fp: FramePoints, pieces, piece_thing: np.ndarray, things: np.ndarray, classes: np.ndarray
    ) -> np.ndarray:
        """Pairs of things of one object class that are one thing: they share a border, come within
        :data:`TOUCHING` of each other in space, or lie within the size of one thing of their class (the pieces of
        a bowl seen around the can in it)."""
        objects = np.isin(classes, self._object_classes())
        a, b = piece_thing[pieces.borders.pairs[:, 0]], piece_thing[pieces.borders.pairs[:, 1]]
        bordering = (a != b) & (classes[a] == classes[b]) & objects[a]
        pairs = [np.stack([a[bordering], b[bordering]], axis=1)]
        flat, points = things.ravel(), fp.points.reshape(-1, 3)
        for c in np.unique(classes[objects]):
            members = [k for k in np.flatnonzero(classes == c)]
            clouds = {k: _sample(points[flat == k]) for k in members}
            members = [k for k in members if len(clouds[k])]
            groups = [[k] for k in members]
            while len(groups) > 1:
                best = None
                for i in range(len(groups)):
                    for j in range(i + 1, len(groups)):
                        ci = np.concatenate([clouds[k] for k in groups[i]])
                        cj = np.concatenate([clouds[k] for k in groups[j]])
                        gap = float(cKDTree(ci).query(cj, k=1)[0].min())
                        if (gap < TOUCHING or _diameter(np.vstack([ci, cj])) <= self._span[c] + SPAN_SLACK) and (
                            best is None or gap < best[0]
                        ):
                            best = (gap, i, j)
                if best is None:
                    break
                _, i, j = best
                pairs.append(np.array([[groups[i][0], groups[j][0]]]))
                groups[i] += groups.pop(j)
        return np.concatenate(pairs)

    def _decide(self, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each row's class and its probability, leaving out the classes no thing of its size can be."""
        probabilities = self.model.classifier.probabilities(rows)
        size = np.maximum(rows[:, RISE], rows[:, EXTENT])
        probabilities *= size[:, None] <= self._largest[None, :]
        probabilities /= np.maximum(probabilities.sum(axis=1, keepdims=True), 1e-12)
        return probabilities.argmax(axis=1), probabilities.max(axis=1)

    def _classify(self, fp: FramePoints, seg: Segmentation, things: np.ndarray, count: int):
        if count == 0:
            return np.zeros(0, dtype=int), np.zeros(0)
        flat = things.ravel()
        order = np.argsort(flat, kind="stable")
        bounds = np.searchsorted(flat[order], np.arange(count + 1))
        rows = np.array(
            [features_of_pixels(fp, order[bounds[k] : bounds[k + 1]], seg.table_height) for k in range(count)]
        )
        return self._decide(rows)

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
        out = []
        for k, options in candidates.items():
            pixels = seen.pixels(k)
            if pixels.size * seen.frame.stride**2 < MIN_PIXELS:
                continue
            label = max(options)[2]
            out.append(Detection2D(label, seen.box(pixels), float(seen.scores[k])))
        return out

    def _specificity(self, match: PhraseMatch, class_index: int) -> int:
        return max((match.specificity.get(t, 0) for t in self._types[class_index]), default=0)

    def _furniture(self, seen: FrameThings, wanted: list[str]) -> list[Detection2D]:
        asked = [f for f in self.furniture if normalize_phrase(f.name) in wanted]
        if not asked:
            return []
        flat = seen.things.ravel()
        thing_class = np.where(flat >= 0, seen.classes[np.maximum(flat, 0)], self._other_class)
        body = np.flatnonzero((flat >= 0) & (thing_class == self._furniture_class))
        handles = [seen.pixels(k) for k in np.flatnonzero(seen.classes == self._handle_class)]
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

