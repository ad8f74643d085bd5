"""Training the perception detector (``roboscript train-detector``): scenes rendered from generated worlds on the
fly, the merging network and the classifier fitted to them, and the result scored on scenes of worlds it never saw.

Everything follows from the seed: training worlds are worlds ``0..n-1`` of the ``detector_scenes`` recipe for the
seed, validation worlds those of the seed plus :data:`VALIDATION_OFFSET`; the networks' initial weights and
minibatches come from the seed too. Scenes are rendered by ``jobs`` worker processes, one world at a time, and put
back in world order, so the result does not depend on how many there were.
"""

from __future__ import annotations

import multiprocessing
import time
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field

import numpy as np

from roboscript.detector_training.classes import class_names, look_alike_classes
from roboscript.detector_training.evaluation import DetectionScores, score_views
from roboscript.detector_training.samples import ViewSamples, view_samples
from roboscript.detector_training.scenes import LabelledView, scene_views
from roboscript.perception.detection.detector_model import FORMAT, DetectorModel
from roboscript.perception.detection.mlp import MLP, Training, train_mlp

VALIDATION_OFFSET = 100_003  # the validation worlds' seed, from the training seed
Progress = Callable[[str], None]


@dataclass(frozen=True)
class TrainingSettings:
    """What ``train-detector`` does: how many training and validation worlds, with how many worker processes,
    and how each network is trained."""

    seed: int = 0
    worlds: int = 500
    validation_worlds: int = 16
    jobs: int = 2
    merger: Training = field(default_factory=lambda: Training(hidden=(64, 32), epochs=40))
    classifier: Training = field(default_factory=lambda: Training(hidden=(128, 64), epochs=60))

    def __post_init__(self) -> None:
        if self.worlds < 1 or self.validation_worlds < 0 or self.jobs < 1:
            raise ValueError(
                f"training needs at least 1 world and 1 job, and no negative number of validation worlds; got "
                f"worlds={self.worlds}, validation_worlds={self.validation_worlds}, jobs={self.jobs}"
            )


def _world_samples(seed: int, index: int, class_of_type: dict[str, str]) -> list[ViewSamples]:
    return [view_samples(v, class_of_type) for v in scene_views(seed, index)]


def collect(
    seed: int, worlds: int, class_of_type: dict[str, str], jobs: int, progress: Progress | None = None
) -> list[ViewSamples]:
    """The samples of worlds ``0..worlds-1`` of ``seed``, in world order."""
    out: list[list[ViewSamples]] = [[] for _ in range(worlds)]
    start = time.perf_counter()
    if jobs == 1:
        for k in range(worlds):
            out[k] = _world_samples(seed, k, class_of_type)
            _report(progress, k + 1, worlds, start)
        return [s for world in out for s in world]
    # Fresh interpreters: each renders with a GL context of its own.
    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("spawn")) as pool:
        futures = {pool.submit(_world_samples, seed, k, class_of_type): k for k in range(worlds)}
        for done, future in enumerate(as_completed(futures), start=1):
            out[futures[future]] = future.result()
            _report(progress, done, worlds, start)
    return [s for world in out for s in world]


def _report(progress: Progress | None, done: int, total: int, start: float) -> None:
    if progress is not None and (done == total or done % max(1, total // 20) == 0):
        elapsed = time.perf_counter() - start
        progress(f"  {done}/{total} worlds rendered ({elapsed:.0f} s)")


def train_detector(settings: TrainingSettings, progress: Progress | None = None) -> DetectorModel:
    """A detector trained as ``settings`` say, its evaluation on the validation worlds in its ``info``."""
    say = progress or (lambda _: None)
    class_of_type = look_alike_classes()
    classes = class_names(class_of_type)
    say(f"rendering {settings.worlds} training worlds (seed {settings.seed}) with {settings.jobs} processes")
    samples = collect(settings.seed, settings.worlds, class_of_type, settings.jobs, progress)
    pairs, together, segments, labels = stack(samples, classes)
    say(f"training the merging network on {len(pairs)} borders ({together.mean():.0%} inside one thing)")
    merger = train_mlp(pairs, together, 2, settings.merger, settings.seed)
    say(f"training the classifier on {len(segments)} segments of {len(set(labels.tolist()))} classes")
    classifier = train_mlp(segments, labels, len(classes), settings.classifier, settings.seed + 1)
    model = DetectorModel(merger, classifier, classes)
    info: dict = {
        "format": FORMAT,
        "settings": _settings_dict(settings),
        "training": {"views": len(samples), "borders": len(pairs), "segments": len(segments)},
        "merger_training_accuracy": accuracy(merger, pairs, together),
        "classifier_training_accuracy": accuracy(classifier, segments, labels),
    }
    if settings.validation_worlds:
        seed = settings.seed + VALIDATION_OFFSET
        say(f"scoring on {settings.validation_worlds} validation worlds (seed {seed})")
        held_out = collect(seed, settings.validation_worlds, class_of_type, settings.jobs, progress)
        v_pairs, v_together, v_segments, v_labels = stack(held_out, classes)
        info["merger_validation_accuracy"] = accuracy(merger, v_pairs, v_together)
        info["classifier_validation_accuracy"] = accuracy(classifier, v_segments, v_labels)
        scores = score_views(model, _validation_views(seed, settings.validation_worlds))
        info["validation_detection"] = scores.as_dict()
        info["validation_summary"] = summary(scores)
    model.info = info
    return model


def _validation_views(seed: int, worlds: int) -> Iterator[LabelledView]:
    for k in range(worlds):
        yield from scene_views(seed, k)


def stack(samples: list[ViewSamples], classes: list[str]):
    """Border features and targets, segment features and class indices, over all ``samples``."""
    index = {name: k for k, name in enumerate(classes)}
    pairs = np.concatenate([s.pair_features for s in samples]) if samples else np.zeros((0, 0))
    together = np.concatenate([s.pair_targets for s in samples]) if samples else np.zeros(0, dtype=int)
    segments = np.concatenate([s.segment_features for s in samples]) if samples else np.zeros((0, 0))
    labels = np.array([index[c] for s in samples for c in s.segment_classes], dtype=np.int64)
    return pairs, together, segments, labels


def accuracy(network: MLP, x: np.ndarray, y: np.ndarray) -> float:
    if len(x) == 0:
        return float("nan")
    return float(np.mean(network.probabilities(x).argmax(axis=1) == y))


def summary(scores: DetectionScores) -> str:
    lines = [
        f"objects (per view, IoU >= 0.5): {scores.objects.line()} over {scores.views} views",
        f"furniture parts: {scores.parts.line()}",
    ]
    if scores.objects.missed:
        lines.append("most missed: " + ", ".join(f"{n} ({c})" for n, c in scores.objects.missed.most_common(8)))
    if scores.objects.wrong:
        lines.append("most mistaken: " + ", ".join(f"{n} ({c})" for n, c in scores.objects.wrong.most_common(8)))
    if scores.parts.missed:
        lines.append("parts missed: " + ", ".join(f"{n} ({c})" for n, c in scores.parts.missed.most_common(8)))
    return "\n".join(lines)


def _settings_dict(settings: TrainingSettings) -> dict:
    out = asdict(settings)
    for key in ("merger", "classifier"):
        out[key]["hidden"] = list(out[key]["hidden"])
    return out
