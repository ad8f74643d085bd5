"""A small multilayer perceptron in NumPy: ReLU layers, a softmax over classes, trained with Adam.

Small enough that the perception detector ships its weights in the package and runs without a deep-learning
framework; inputs are standardised with the training set's mean and spread, which travel with the weights.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np


@dataclass
class MLP:
    """Weights and biases of each layer, and the inputs' standardisation."""

    weights: list[np.ndarray]
    biases: list[np.ndarray]
    mean: np.ndarray
    scale: np.ndarray

    @property
    def inputs(self) -> int:
        return int(self.weights[0].shape[0])

    @property
    def outputs(self) -> int:
        return int(self.weights[-1].shape[1])

    def logits(self, x: np.ndarray) -> np.ndarray:
        x = np.asarray(x, dtype=np.float64)
        if x.ndim != 2 or x.shape[1] != self.inputs:
            raise ValueError(f"the network takes rows of {self.inputs} features, got an array of shape {x.shape}")
        h = (x - self.mean) / self.scale
        for w, b in zip(self.weights[:-1], self.biases[:-1], strict=True):
            h = np.maximum(h @ w + b, 0.0)
        return h @ self.weights[-1] + self.biases[-1]

    def probabilities(self, x: np.ndarray) -> np.ndarray:
        """Each row's probability of each class, (n, classes)."""
        return softmax(self.logits(x))

    def arrays(self, prefix: str) -> dict[str, np.ndarray]:
        """The network as named arrays (for ``np.savez``), each name starting with ``prefix``."""
        out = {f"{prefix}mean": self.mean, f"{prefix}scale": self.scale}
        for k, (w, b) in enumerate(zip(self.weights, self.biases, strict=True)):
            out[f"{prefix}w{k}"], out[f"{prefix}b{k}"] = w, b
        return out

    @classmethod
    def from_arrays(cls, arrays, prefix: str) -> MLP:
        """The network :meth:`arrays` wrote under ``prefix``."""
        layers = sum(1 for name in arrays if name.startswith(f"{prefix}w"))
        if layers == 0:
            raise KeyError(f"no network stored under {prefix!r}")
        return cls(
            [np.asarray(arrays[f"{prefix}w{k}"]) for k in range(layers)],
            [np.asarray(arrays[f"{prefix}b{k}"]) for k in range(layers)],
            np.asarray(arrays[f"{prefix}mean"]),
            np.asarray(arrays[f"{prefix}scale"]),
        )


def softmax(logits: np.ndarray) -> np.ndarray:
    z = logits - logits.max(axis=1, keepdims=True)
    e = np.exp(z)
    return e / e.sum(axis=1, keepdims=True)


@dataclass(frozen=True)
class Training:
    """How a network is trained: hidden layer widths, passes over the data, Adam's step, L2 weight decay,
    minibatch size, and how much rare classes are weighted up (0: not at all, 1: to equal total weight)."""

    hidden: tuple[int, ...] = (64,)
    epochs: int = 40
    learning_rate: float = 3e-3
    weight_decay: float = 1e-4
    batch: int = 256
    balance: float = 0.5


def train_mlp(x: np.ndarray, y: np.ndarray, classes: int, training: Training, seed: int) -> MLP:
    """A network fitted to rows ``x`` with class indices ``y`` (0..classes-1), reproducibly from ``seed``."""
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.int64)
    if len(x) != len(y) or len(x) == 0:
        raise ValueError(f"training needs as many labels as rows, and some rows: got {len(x)} rows, {len(y)} labels")
    rng = np.random.default_rng(seed)
    mean = x.mean(axis=0)
    scale = x.std(axis=0) + 1e-6
    sizes = [x.shape[1], *training.hidden, classes]
    weights = [rng.normal(0, np.sqrt(2.0 / a), (a, b)) for a, b in itertools.pairwise(sizes)]
    biases = [np.zeros(b) for b in sizes[1:]]
    counts = np.bincount(y, minlength=classes).astype(float)
    class_weight = np.where(counts > 0, (counts.max() / np.maximum(counts, 1)) ** training.balance, 0.0)
    sample_weight = class_weight[y] / class_weight[y].mean()
    params = weights + biases
    m = [np.zeros_like(p) for p in params]
    v = [np.zeros_like(p) for p in params]
    xs = (x - mean) / scale
    step = 0
    for _ in range(training.epochs):
        order = rng.permutation(len(xs))
        for start in range(0, len(xs), training.batch):
            batch = order[start : start + training.batch]
            grads = _gradients(weights, biases, xs[batch], y[batch], sample_weight[batch], training.weight_decay)
            step += 1
            for k, (p, g) in enumerate(zip(params, grads, strict=True)):
                m[k] = 0.9 * m[k] + 0.1 * g
                v[k] = 0.999 * v[k] + 0.001 * g * g
                p -= training.learning_rate * (m[k] / (1 - 0.9**step)) / (np.sqrt(v[k] / (1 - 0.999**step)) + 1e-8)
    return MLP(weights, biases, mean, scale)


def _gradients(weights, biases, x, y, sample_weight, decay) -> list[np.ndarray]:
    activations = [x]
    h = x
    for w, b in zip(weights[:-1], biases[:-1], strict=True):
        h = np.maximum(h @ w + b, 0.0)
        activations.append(h)
    p = softmax(h @ weights[-1] + biases[-1])
    p[np.arange(len(y)), y] -= 1.0
    delta = p * sample_weight[:, None] / len(y)
    grad_w, grad_b = [], []
    for k in range(len(weights) - 1, -1, -1):
        grad_w.append(activations[k].T @ delta + decay * weights[k])
        grad_b.append(delta.sum(axis=0))
        if k:
            delta = (delta @ weights[k].T) * (activations[k] > 0)
    return grad_w[::-1] + grad_b[::-1]
