"""The perception detector's learned parts, as one file: the network that joins pieces into things, the network
that tells what a thing is, the classes it tells apart, and how it was trained.

The package ships one (``perception/detection/models/detector.npz``), made by ``roboscript train-detector``; a user may
point ``--detector trained:PATH`` at their own.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

import numpy as np

from roboscript.perception.detection.detectors import DetectorError
from roboscript.perception.detection.mlp import MLP
from roboscript.perception.detection.piece_pairs import PAIR_FEATURES
from roboscript.perception.detection.segment_features import SEGMENT_FEATURES

FORMAT = "roboscript-detector/1"
FURNITURE = "furniture"  # the class of a cabinet's carcass, fronts and insides: its parts are told apart by geometry
HANDLE = "handle"  # the class of furniture's handles
OTHER = "other"  # the class of what is no object of the library (the robot's edges, mixtures)


class DetectorModelError(DetectorError):
    """A detector model file is missing, unreadable or of another format; the message says which."""


@dataclass
class DetectorModel:
    """``classes``: each class's object types joined by ``+`` (types that look the same, such as two white mugs,
    share one), then :data:`FURNITURE`, :data:`HANDLE` and :data:`OTHER`; ``info``: how it was trained and how it
    scored."""

    merger: MLP
    classifier: MLP
    classes: list[str]
    info: dict = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.merger.inputs != PAIR_FEATURES or self.merger.outputs != 2:
            raise DetectorModelError(
                f"the merging network takes {self.merger.inputs} features to {self.merger.outputs} classes; "
                f"this version needs {PAIR_FEATURES} to 2: retrain with roboscript train-detector"
            )
        if self.classifier.inputs != SEGMENT_FEATURES or self.classifier.outputs != len(self.classes):
            raise DetectorModelError(
                f"the classifier takes {self.classifier.inputs} features to {self.classifier.outputs} classes "
                f"({len(self.classes)} named); this version needs {SEGMENT_FEATURES} features: retrain with "
                "roboscript train-detector"
            )

    def types_of(self, index: int) -> tuple[str, ...]:
        """The object types class ``index`` stands for (none for furniture, handles and other)."""
        name = self.classes[index]
        return () if name in (FURNITURE, HANDLE, OTHER) else tuple(name.split("+"))

    def save(self, path: str | os.PathLike) -> Path:
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        arrays = {**self.merger.arrays("merger_"), **self.classifier.arrays("classifier_")}
        meta = json.dumps({"format": FORMAT, "classes": self.classes, "info": self.info})
        with open(path, "wb") as out:
            np.savez_compressed(out, meta=np.array(meta), **arrays)
        return path


def load_detector_model(path: str | os.PathLike | None = None) -> DetectorModel:
    """The model in ``path``, or the packaged one; raises :class:`DetectorModelError`."""
    path = Path(path) if path is not None else packaged_model_path()
    if not path.is_file():
        raise DetectorModelError(
            f"no detector model at {str(path)!r}; make one with roboscript train-detector --out {path}"
        )
    try:
        with np.load(path, allow_pickle=False) as arrays:
            meta = json.loads(str(arrays["meta"]))
            if meta.get("format") != FORMAT:
                raise DetectorModelError(f"{str(path)!r} is a {meta.get('format')!r} file, not {FORMAT!r}")
            return DetectorModel(
                MLP.from_arrays(arrays, "merger_"),
                MLP.from_arrays(arrays, "classifier_"),
                list(meta["classes"]),
                dict(meta.get("info", {})),
            )
    except (OSError, KeyError, ValueError) as exc:
        if isinstance(exc, DetectorModelError):
            raise
        raise DetectorModelError(f"could not read the detector model {str(path)!r}: {exc}") from exc


def check_model_file(path: str | os.PathLike) -> str:
    """``path`` as a string if a file is there (its contents are read when the detector is built)."""
    if not Path(path).is_file():
        raise DetectorModelError(
            f"no detector model file at {str(path)!r}; make one with roboscript train-detector --out FILE.npz, or "
            "give trained alone for the packaged model"
        )
    return os.fspath(path)


def packaged_model_path() -> Path:
    return Path(str(resources.files("roboscript") / "perception" / "detection" / "models" / "detector.npz"))
