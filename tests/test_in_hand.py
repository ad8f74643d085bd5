"""Where a held object sits in the hand, from a partial look at it there (perception/reconstruction/in_hand.py)."""

import math

import numpy as np

from roboscript.geometry import Transform
from roboscript.perception.reconstruction.in_hand import register

UNTURNED = np.array([0.0, 0.0, 0.0, 1.0])


def _mug(rng: np.random.Generator) -> np.ndarray:
    """A mug's outer surface as fusion gives it: a cylinder 8 cm across and 9.5 cm high with a handle on one
    side, 3,000 points."""
    angle = rng.uniform(0.0, 2.0 * math.pi, 2400)
    height = rng.uniform(0.0, 0.095, 2400)
    wall = np.stack([0.04 * np.cos(angle), 0.04 * np.sin(angle), height], axis=1)
    turn = rng.uniform(0.0, 2.0 * math.pi, 600)
    across = rng.uniform(-0.006, 0.006, 600)
    handle = np.stack([0.055 + 0.02 * np.cos(turn), across, 0.05 + 0.025 * np.sin(turn)], axis=1)
    return np.concatenate([wall, handle]) + np.array([0.3, -0.1, 0.82])


def _lifted_and_tipped(pivot: np.ndarray, degrees: float, lift: float) -> Transform:
    """Lifted by ``lift`` metres and turned by ``degrees`` about the y axis through ``pivot`` (the fingers)."""
    half = math.radians(degrees) / 2.0
    turn = Transform(np.zeros(3), np.array([0.0, math.sin(half), 0.0, math.cos(half)]))
    return Transform(pivot + np.array([0.0, 0.0, lift]), UNTURNED).compose(turn).compose(Transform(-pivot, UNTURNED))


def test_a_mug_that_tipped_in_the_hand_is_found_from_the_part_the_cameras_see():
    rng = np.random.default_rng(1)
    model = _mug(rng)
    truth = _lifted_and_tipped(np.array([0.26, -0.1, 0.915]), 10.0, 0.05)  # held at the rim, tipped as it rose
    moved = truth.apply(model)
    # The cameras see the side facing +x, below the hand, with depth noise.
    seen = moved[(model[:, 0] > 0.29) & (model[:, 2] < 0.9)]
    seen = seen + rng.normal(0.0, 0.0008, seen.shape)
    expected = model + np.array([0.0, 0.0, 0.05])  # lifted as it was taken
    assert moved[:, 2].min() < expected[:, 2].min() - 0.01
    motion = register(expected, seen)
    assert motion is not None
    found = motion.apply(expected)
    assert np.max(np.linalg.norm(found - moved, axis=1)) < 0.006
    # The lowest point, which a place pose must allow for, within 3 mm.
    assert abs(found[:, 2].min() - moved[:, 2].min()) < 0.003


def test_too_little_seen_or_a_shape_that_does_not_fit_tells_nothing():
    rng = np.random.default_rng(2)
    model = _mug(rng)
    assert register(model, model[:20]) is None
    scattered = rng.uniform(-0.3, 0.3, (800, 3)) + np.array([0.3, -0.1, 1.0])
    assert register(model, scattered) is None
    far = model + np.array([0.0, 0.0, 0.2])  # the same shape, 20 cm off: not where the hand holds it
    assert register(model, far) is None


def test_an_object_where_it_was_expected_or_seen_higher_stays_where_it_was_expected():
    rng = np.random.default_rng(3)
    model = _mug(rng)
    side = model[model[:, 0] > 0.3]
    assert register(model, side + rng.normal(0.0, 0.0008, side.shape)) is None
    # Tipped and 2 cm higher than the fingers can have taken it (bits of the fingers taken for it): not believed.
    raised = _lifted_and_tipped(np.array([0.26, -0.1, 0.915]), 10.0, 0.02).apply(model)
    assert register(model, raised[(model[:, 0] > 0.29) & (model[:, 2] < 0.9)]) is None
