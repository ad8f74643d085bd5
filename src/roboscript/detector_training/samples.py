"""Training samples from labelled views: the borders between pieces, marked "one thing" or "two", for the merging
network, and segments with their class for the classifier.

Each piece of a view's class-agnostic segmentation takes the entity most of its pixels show in the simulator's
segmentation. A border joins two pieces of one entity; the classifier learns from the segments the pieces of each
entity make together (what a perfect merge gives) and from single pieces that show one entity alone (what a
merge that stopped short gives). Pieces of the robot (the self-filter's fringe), and of nothing, are of the class
:data:`~roboscript.perception.detection.detector_model.OTHER`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from roboscript.detector_training.scenes import EntityLabel, LabelledView
from roboscript.names import kind_of
from roboscript.perception.detection.detector_model import FURNITURE, HANDLE, OTHER
from roboscript.perception.detection.segment_features import SEGMENT_FEATURES, features_of_pixels
from roboscript.perception.detection.segment_merging import describe_pieces
from roboscript.perception.detection.segments import frame_points, segment

PURE = 0.8  # share of a piece's pixels one entity must have for the piece to teach what that entity looks like
MIXED = 0.5  # pieces less pure than this teach nothing about borders


@dataclass
class ViewSamples:
    """What one view teaches: border features and targets (1: one thing), segment features and class names."""

    pair_features: np.ndarray  # (m, PAIR_FEATURES)
    pair_targets: np.ndarray  # (m,) int
    segment_features: np.ndarray  # (s, SEGMENT_FEATURES)
    segment_classes: list[str]
    world: str


def entity_class(label: EntityLabel | None, class_of_type: Mapping[str, str]) -> str:
    """The detector's class of an entity: its object type's class, furniture, a handle, or other."""
    if label is None:
        return OTHER
    if label.kind == "object":
        return class_of_type.get(label.type_name, OTHER)
    if label.kind == "furniture" or (label.kind == "part" and kind_of(label.name) != "handle"):
        return FURNITURE
    if label.kind == "part":
        return HANDLE
    return OTHER


def view_samples(view: LabelledView, class_of_type: Mapping[str, str]) -> ViewSamples:
    """The samples of ``view`` (its robot mask from the self-filter, as at run time)."""
    fp = frame_points(view.frame, view.robot_mask)
    seg = segment(fp)
    pieces = describe_pieces(seg)
    truth = view.frame.segmentation[:: fp.stride, :: fp.stride]
    major, purity = _majority(seg.labels, truth, seg.count)
    a, b = pieces.borders.pairs[:, 0], pieces.borders.pairs[:, 1]
    usable = (purity[a] >= MIXED) & (purity[b] >= MIXED)
    targets = (major[a] == major[b]) & (major[a] >= 0)
    features, classes = [], []
    flat = seg.labels.ravel()
    for entity in np.unique(major[major >= 0]):
        mine = np.flatnonzero(major == entity)
        label = entity_class(view.labels.get(int(entity)), class_of_type)
        groups = [mine] if len(mine) == 1 else [mine, *([k] for k in mine if purity[k] >= PURE)]
        for group in groups:
            pixels = np.flatnonzero(np.isin(flat, group))
            features.append(features_of_pixels(fp, pixels, seg.table_height))
            classes.append(label)
    for k in np.flatnonzero(major < 0):  # nothing's, or the robot's
        features.append(features_of_pixels(fp, np.flatnonzero(flat == k), seg.table_height))
        classes.append(OTHER)
    return ViewSamples(
        pieces.features[usable],
        targets[usable].astype(np.int64),
        np.array(features).reshape(-1, SEGMENT_FEATURES),
        classes,
        view.world,
    )


def _majority(labels: np.ndarray, truth: np.ndarray, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Per piece, the entity most of its pixels show (-1: the robot's or nothing's) and that entity's share."""
    keep = labels >= 0
    pieces, entities = labels[keep], truth[keep].astype(np.int64)
    entities = np.where(entities < 0, -1, entities)
    offset = entities.max(initial=0) + 2
    keys = pieces * offset + (entities + 1)
    unique, counts = np.unique(keys, return_counts=True)
    piece_of, entity_of = unique // offset, unique % offset - 1
    totals = np.bincount(pieces, minlength=count)
    major = np.full(count, -1)
    share = np.zeros(count)
    best = np.zeros(count)
    order = np.argsort(counts, kind="stable")
    for p, e, c in zip(piece_of[order], entity_of[order], counts[order], strict=True):
        if c >= best[p]:
            best[p], major[p] = c, e
    share = best / np.maximum(totals, 1)
    return major, share
