"""Open-vocabulary 2D detectors through ``transformers`` (the ``detectors`` extra): OWLv2 and Grounding DINO.

Weights are the user's: a directory as ``save_pretrained`` writes it (config, weights, processor and tokenizer
files), e.g. a download of ``google/owlv2-base-patch16-ensemble`` or ``IDEA-Research/grounding-dino-tiny``. Nothing
is fetched from a hub. Each box gets one label: where boxes of different phrases overlap, the best one stays.
"""

from __future__ import annotations

import os
from collections.abc import Sequence

import numpy as np

from roboscript import extras
from roboscript.errors import RoboScriptError
from roboscript.perception.detection.grounding import Detection2D, Grounder, image_box_iou, normalize_phrase
from roboscript.robot_io import CameraFrame

DETECTOR_KINDS = ("owlv2", "grounding-dino")
# The model's configuration, and the processor's (older transformers write preprocessor_config.json).
REQUIRED_FILES = ("config.json", ("processor_config.json", "preprocessor_config.json"))


class DetectorError(RoboScriptError, RuntimeError):
    """A detector could not be loaded or run; the message says what is missing."""


def check_model_dir(kind: str, model_dir: str | os.PathLike) -> str:
    """``model_dir`` as a path if it holds a model of ``kind`` (by its files; nothing is loaded)."""
    if kind not in DETECTOR_KINDS:
        raise DetectorError(f"unknown detector {kind!r}; detectors: {', '.join(DETECTOR_KINDS)}")
    path = os.fspath(model_dir)
    missing = [
        " or ".join(names)
        for names in ((f,) if isinstance(f, str) else f for f in REQUIRED_FILES)
        if not any(os.path.isfile(os.path.join(path, n)) for n in names)
    ]
    if not os.path.isdir(path) or missing:
        raise DetectorError(
            f"no {kind} model in {path!r} (missing: {', '.join(missing) or 'the directory'}); give a directory "
            "written by save_pretrained, with its weights, processor and tokenizer files"
        )
    return path


class OpenVocabularyDetector(Grounder):
    """``kind``: ``owlv2`` or ``grounding-dino``; ``model_dir``: the weights; boxes scoring below ``threshold``
    are dropped, and of boxes overlapping by more than ``overlap`` IoU only the best is kept."""

    def __init__(self, kind: str, model_dir: str | os.PathLike, threshold: float = 0.2, overlap: float = 0.5):
        path = check_model_dir(kind, model_dir)
        try:
            import torch
            from transformers import AutoProcessor, GroundingDinoForObjectDetection, Owlv2ForObjectDetection
        except ImportError as exc:
            raise DetectorError(f"{extras.missing_text('detectors', 'open-vocabulary detectors')} ({exc})") from exc
        model_class = Owlv2ForObjectDetection if kind == "owlv2" else GroundingDinoForObjectDetection
        try:
            self.processor = AutoProcessor.from_pretrained(path, local_files_only=True)
            self.model = model_class.from_pretrained(path, local_files_only=True).eval()
        except (OSError, ValueError) as exc:
            raise DetectorError(f"could not load the {kind} model in {path!r}: {exc}") from exc
        self.kind, self.threshold, self.overlap = kind, threshold, overlap
        self._torch = torch

    def detect(self, frame: CameraFrame, phrases: Sequence[str]) -> list[Detection2D]:
        wanted = [normalize_phrase(p) for p in phrases]
        if not wanted:
            return []
        h, w = frame.rgb.shape[:2]
        with self._torch.no_grad():
            if self.kind == "owlv2":
                boxes, scores, labels = self._owlv2(frame.rgb, wanted, h, w)
            else:
                boxes, scores, labels = self._grounding_dino(frame.rgb, wanted, h, w)
        return _best_per_place(boxes, scores, labels, w, h, self.overlap)

    def _owlv2(self, rgb: np.ndarray, wanted: list[str], h: int, w: int):
        inputs = self.processor(text=[wanted], images=rgb, return_tensors="pt", padding="max_length", truncation=True)
        outputs = self.model(**inputs)
        side = max(h, w)  # OWLv2 pads the image to a square before scaling it
        result = self.processor.post_process_grounded_object_detection(
            outputs, threshold=self.threshold, target_sizes=[(side, side)], text_labels=[wanted]
        )[0]
        labels = [wanted[int(i)] for i in result["labels"]]
        return result["boxes"].detach().numpy(), result["scores"].detach().numpy(), labels

    def _grounding_dino(self, rgb: np.ndarray, wanted: list[str], h: int, w: int):
        text = " ".join(f"{p}." for p in wanted)  # the model's prompt form: "apple. footed bowl."
        inputs = self.processor(images=rgb, text=text, return_tensors="pt")
        outputs = self.model(**inputs)
        result = self.processor.post_process_grounded_object_detection(
            outputs,
            inputs["input_ids"],
            threshold=self.threshold,
            text_threshold=self.threshold,
            target_sizes=[(h, w)],
        )[0]
        raw = result["text_labels"] if "text_labels" in result else result["labels"]
        labels = [closest_phrase(str(label), wanted) for label in raw]
        return result["boxes"].detach().numpy(), result["scores"].detach().numpy(), labels


def closest_phrase(text: str, wanted: Sequence[str]) -> str | None:
    """The phrase asked for that a model's label names (it may return part of a phrase, or run two together)."""
    text = normalize_phrase(text)
    if text in wanted:
        return text
    words = set(text.split())
    scored = [(len(words & set(p.split())), p) for p in wanted]
    best = max(scored, default=(0, None))
    return best[1] if best[0] > 0 else None


def _best_per_place(boxes, scores, labels, w: int, h: int, overlap: float) -> list[Detection2D]:
    """Boxes clipped to the image, best first; a box overlapping a better one by more than ``overlap`` goes."""
    kept: list[Detection2D] = []
    for k in np.argsort(-np.asarray(scores, dtype=float)):
        if labels[k] is None:
            continue
        x0, y0, x1, y1 = (float(v) for v in boxes[k])
        box = (int(np.clip(np.floor(x0), 0, w - 1)), int(np.clip(np.floor(y0), 0, h - 1)),
               int(np.clip(np.ceil(x1), 1, w)), int(np.clip(np.ceil(y1), 1, h)))  # fmt: skip
        if box[2] <= box[0] or box[3] <= box[1]:
            continue
        if any(image_box_iou(box, other.box) > overlap for other in kept):
            continue
        kept.append(Detection2D(labels[k], box, float(scores[k])))
    return kept

