"""Seeing things in one RGB-D frame, before any phrase: the frame cut into pieces
(:mod:`roboscript.perception.detection.segments`), the pieces joined into things by the learned merging network
(:mod:`roboscript.perception.detection.segment_merging`), each thing classified by the learned classifier into one of
the object library's look-alike classes, furniture, a handle or other
(:mod:`roboscript.perception.detection.detector_model`), and things of one class the merge left apart joined.

Pixels whose depth is 0 are not looked at: the pipeline zeroes the robot's own (its self-filter's mask).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from roboscript.objects import object_types
from roboscript.perception.detection.detector_model import FURNITURE, HANDLE, OTHER, DetectorModel
from roboscript.perception.detection.pixel_masks import opened
from roboscript.perception.detection.segment_features import EXTENT, RISE, features_of_pixels
from roboscript.perception.detection.segment_merging import describe_pieces, merge, union
from roboscript.perception.detection.segments import FramePoints, Segmentation, frame_points, segment
from roboscript.perception.points import evenly_spread
from roboscript.robot_io import CameraFrame

BOX_PADDING = 1  # working pixels a box is grown by on every side
TOUCHING = 0.012  # metres: things of one class closer than this are one thing
SPAN_SLACK = 0.01  # metres beyond its class's widest footprint that pieces of one thing may spread over
SIZE_SLACK = (1.2, 0.03)  # a thing may measure this much (times, plus metres) more than its class's largest
SAMPLE = 200  # points of each thing compared when measuring how close two are
PLAUSIBLE = 0.05  # the probability below which the network rules a class out, whatever the scene holds


def _diameter(points: np.ndarray) -> float:
    """The largest horizontal distance between two of ``points``."""
    xy = points[:, :2]
    return float(np.sqrt(((xy[:, None, :] - xy[None, :, :]) ** 2).sum(axis=-1).max()))


def _sample(points: np.ndarray) -> np.ndarray:
    """At most :data:`SAMPLE` of the finite ``points``, evenly spread through the array."""
    return evenly_spread(points[np.isfinite(points).all(axis=1)], SAMPLE)


@dataclass
class FrameThings:
    """What one frame shows, before any phrase: the working-resolution image of each thing's index (-1: none),
    each thing's class index and probability, and the pairs of things that border each other in the image."""

    frame: FramePoints
    segmentation: Segmentation
    things: np.ndarray  # (h, w) int
    classes: np.ndarray  # (n,) int
    scores: np.ndarray  # (n,)
    adjacent: np.ndarray  # (m, 2) int, each pair once

    def pixels(self, thing: int) -> np.ndarray:
        return np.flatnonzero(self.things.ravel() == thing)

    def box(self, pixels: np.ndarray) -> tuple[int, int, int, int]:
        """The full-resolution box ``(x0, y0, x1, y1)`` of working pixels (flat indices), grown by
        :data:`BOX_PADDING` working pixels: a thing's outermost pixels, where the depth steps off it, and its
        lowest few millimetres, next to the table, are cut off its piece, and the box should hold them."""
        h, w = self.things.shape
        s = self.frame.stride
        # A strip one pixel wide along a thing's edge is most often a bit of what stands behind it that the merge
        # joined (a cabinet's plinth below a basket) and would stretch the box; a thing that is all thin strips (a
        # handle seen edge-on) keeps its pixels.
        mask = np.zeros(h * w, dtype=bool)
        mask[pixels] = True
        kept = np.flatnonzero(opened(mask.reshape(h, w)))
        if kept.size >= 0.5 * len(pixels):
            pixels = kept
        rows, cols = pixels // w, pixels % w
        pad = BOX_PADDING
        return (
            max(int(cols.min()) - pad, 0) * s,
            max(int(rows.min()) - pad, 0) * s,
            min(int(cols.max()) + 1 + pad, w) * s,
            min(int(rows.max()) + 1 + pad, h) * s,
        )


class ThingFinder:
    """Finds and classifies the things of frames with ``model``'s networks."""

    def __init__(self, model: DetectorModel):
        self.model = model
        self.types = [frozenset(model.types_of(k)) for k in range(len(model.classes))]
        library = object_types()
        # The widest a thing of each class is across, seen from above (the diagonal of its footprint).
        self._span = [
            max((float(np.hypot(*library[t].size[:2])) for t in types), default=0.0) for types in self.types
        ]
        # The most a thing of each class can measure in any direction, however it lies (its box's diagonal), with
        # room for the depth images' noise; what measures more is of another class.
        largest = [max((float(np.linalg.norm(library[t].size)) for t in ts), default=np.inf) for ts in self.types]
        self._largest = np.array(largest) * SIZE_SLACK[0] + SIZE_SLACK[1]
        self.furniture_class = model.classes.index(FURNITURE)
        self.handle_class = model.classes.index(HANDLE)
        self.other_class = model.classes.index(OTHER)
        self._objects = np.array([k for k, t in enumerate(self.types) if t])

    def find(self, frame: CameraFrame, present: Collection[str] | None = None) -> FrameThings:
        """The things ``frame`` shows and their classes. ``present``: the object types the scene holds (its
        description's), where that is known; no thing is then of a class that holds none of them."""
        allowed = self._allowed(present)
        fp = frame_points(frame)
        seg = segment(fp)
        pieces = describe_pieces(seg)
        piece_thing = merge(pieces, self.model.merger)
        things = np.full(seg.labels.shape, -1)
        placed = seg.labels >= 0
        things[placed] = piece_thing[seg.labels[placed]]
        count = int(piece_thing.max()) + 1 if piece_thing.size else 0
        classes, scores = self._classify(fp, seg, things, count, allowed)
        # Two things of one object class that touch, in the image or in space, are one thing the merge left in two
        # (a bowl's inside and outside, a mug's handle seen through its gap).
        if count:
            pairs = self._same_class_neighbours(fp, pieces, piece_thing, things, classes)
            if len(pairs):
                joined = union(count, pairs)
                piece_thing = joined[piece_thing]
                things[placed] = piece_thing[seg.labels[placed]]
                count = int(joined.max()) + 1
                classes, scores = self._classify(fp, seg, things, count, allowed)
        a, b = piece_thing[pieces.borders.pairs[:, 0]], piece_thing[pieces.borders.pairs[:, 1]]
        adjacent = np.unique(np.sort(np.stack([a, b], axis=1)[a != b], axis=1), axis=0).reshape(-1, 2)
        return FrameThings(fp, seg, things, classes, scores, adjacent)

    def _same_class_neighbours(
        self, fp: FramePoints, pieces, piece_thing: np.ndarray, things: np.ndarray, classes: np.ndarray
    ) -> np.ndarray:
        """Pairs of things of one object class that are one thing: they share a border, come within
        :data:`TOUCHING` of each other in space, or lie within the size of one thing of their class (the pieces of
        a bowl seen around the can in it)."""
        objects = np.isin(classes, self._objects)
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

    def _allowed(self, present: Collection[str] | None) -> np.ndarray:
        """Which classes a thing may be: all where what the scene holds is unknown; else furniture, handles,
        other things, and the object classes holding one of the ``present`` types."""
        if present is None:
            return np.ones(len(self.types), dtype=bool)
        types = set(present)
        return np.array([not t or bool(t & types) for t in self.types])

    def _decide(self, rows: np.ndarray, allowed: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each row's class and its probability, leaving out the classes no thing of its size can be and those the
        scene does not hold (``allowed``).

        Of the classes the scene holds, a thing is the likeliest, with its share of their probability, where the
        network gives that class :data:`PLAUSIBLE` or more: a green apple seen from above, 0.91 a tennis ball and
        0.09 a green apple in a scene with no tennis ball, is the apple; a green block stacked on a red box, merged
        into one thing and 0.99 a green mug, is no find at all."""
        probabilities = self.model.classifier.probabilities(rows)
        size = np.maximum(rows[:, RISE], rows[:, EXTENT])
        probabilities *= size[:, None] <= self._largest[None, :]
        probabilities /= np.maximum(probabilities.sum(axis=1, keepdims=True), 1e-12)
        held = probabilities * allowed[None, :]
        best = held.argmax(axis=1)
        likeliest = held[np.arange(len(held)), best]
        plausible = likeliest >= PLAUSIBLE
        share = likeliest / np.maximum(held.sum(axis=1), 1e-12)
        return np.where(plausible, best, self.other_class), np.where(plausible, share, 0.0)

    def _classify(self, fp: FramePoints, seg: Segmentation, things: np.ndarray, count: int, allowed: np.ndarray):
        if count == 0:
            return np.zeros(0, dtype=int), np.zeros(0)
        flat = things.ravel()
        order = np.argsort(flat, kind="stable")
        bounds = np.searchsorted(flat[order], np.arange(count + 1))
        rows = np.array(
            [features_of_pixels(fp, order[bounds[k] : bounds[k + 1]], seg.table_height) for k in range(count)]
        )
        return self._decide(rows, allowed)
