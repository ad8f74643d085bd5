"""Joining a frame's pieces into things: a network scores each border between two pieces (one thing, or two), and
pieces joined by a border it believes in become one segment. A bottle and its cap, the two colours of a box, the
faces of a basket's walls come together here; a mug and the plate it stands on stay apart."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from roboscript.perception.detection.mlp import MLP
from roboscript.perception.detection.piece_pairs import Borders, PieceStats, borders, pair_features, piece_stats
from roboscript.perception.detection.segments import Segmentation

JOIN = 0.5  # the probability of "one thing" above which a border joins its pieces
NEAR_SHARE = 0.0  # share of a border's neighbours on one surface above which it may join its pieces


@dataclass
class Pieces:
    """A segmentation with its pieces' stats and borders, and each border's features."""

    segmentation: Segmentation
    stats: PieceStats
    borders: Borders
    features: np.ndarray


def describe_pieces(seg: Segmentation) -> Pieces:
    stats = piece_stats(seg)
    edges = borders(seg)
    return Pieces(seg, stats, edges, pair_features(stats, edges))


def join(pieces: Pieces, together: np.ndarray) -> np.ndarray:
    """Each piece's segment (0..s-1) when the borders marked in ``together`` (bool per border) join their
    pieces."""
    return union(pieces.segmentation.count, pieces.borders.pairs[together])


def union(count: int, pairs: np.ndarray) -> np.ndarray:
    """Each of ``count`` items' group (0..g-1) once the ``pairs`` (m, 2) of items are joined."""
    pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
    graph = coo_matrix((np.ones(len(pairs), dtype=np.int8), (pairs[:, 0], pairs[:, 1])), shape=(count, count))
    return connected_components(graph, directed=False)[1]


def merge(pieces: Pieces, network: MLP, threshold: float = JOIN) -> np.ndarray:
    """Each piece's segment, borders joined where ``network`` (two classes: apart, together) scores "together"
    above ``threshold`` and some of the border lies on one surface."""
    if len(pieces.features) == 0:
        return np.arange(pieces.segmentation.count)
    together = network.probabilities(pieces.features)[:, 1] > threshold
    # Pieces whose border holds no neighbours on one surface touch in the image only, one in front of the other:
    # the network, which rarely saw such borders between two things, joined a basket to the cabinet behind it
    # across one or two pixels. Pieces of one thing seen apart are joined by their class later.
    together &= pieces.borders.near > NEAR_SHARE
    return join(pieces, together)
