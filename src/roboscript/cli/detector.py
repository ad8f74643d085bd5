"""``roboscript train-detector``: trains the perception detector on scenes rendered from generated worlds, prints
how it scores on worlds it never saw, and writes the model file ``--perception full`` can use."""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path


def cmd_train_detector(args: argparse.Namespace) -> int:
    from roboscript.detector_training.train import TrainingSettings, train_detector

    settings = TrainingSettings(
        seed=args.seed, worlds=args.worlds, validation_worlds=args.validation_worlds, jobs=args.jobs
    )
    started = time.perf_counter()
    model = train_detector(settings, progress=lambda line: print(line, file=sys.stderr, flush=True))
    model.info["seconds"] = round(time.perf_counter() - started, 1)
    path = model.save(args.out)
    info = model.info
    print(f"wrote {path} ({path.stat().st_size / 1024:.0f} KiB, {len(model.classes)} classes) in {info['seconds']} s")
    print(
        f"merging network: training accuracy {info['merger_training_accuracy']:.3f}"
        + (f", validation {info['merger_validation_accuracy']:.3f}" if "merger_validation_accuracy" in info else "")
    )
    print(
        f"classifier: training accuracy {info['classifier_training_accuracy']:.3f}"
        + (
            f", validation {info['classifier_validation_accuracy']:.3f}"
            if "classifier_validation_accuracy" in info
            else ""
        )
    )
    if "validation_summary" in info:
        print(info["validation_summary"])
    if args.json:
        Path(args.json).write_text(json.dumps(info, indent=2) + "\n")
    return 0


def add_detector_commands(sub) -> None:
    """``train-detector`` on the ``roboscript`` parser's subcommands."""
    train = sub.add_parser(
        "train-detector",
        help="train the perception detector on generated scenes and score it on unseen ones",
        description=__doc__,
    )
    train.add_argument("--seed", type=int, default=0, help="training worlds 0..N-1 of this seed; validation: another")
    train.add_argument("--worlds", type=int, default=500, help="training worlds (each seen by 3 cameras, 3 poses)")
    train.add_argument("--validation-worlds", type=int, default=16, help="unseen worlds to score on (0: none)")
    train.add_argument("--jobs", type=int, default=2, help="worker processes that render scenes")
    train.add_argument(
        "--out",
        default="out/detector.npz",
        help="the model file (use it with --perception full --detector trained:FILE)",
    )
    train.add_argument("--json", default=None, help="also write how it was trained and how it scored to this file")
    train.set_defaults(func=cmd_train_detector)
