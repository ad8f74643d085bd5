"""The packaged detector's 2D scores on held-out generated scenes, as the code scores them now.

Run: python benchmarks/detector_scores.py [--worlds 16] [--model FILE.npz]

The model file keeps the scores measured when it was trained (``info["validation_summary"]``); this script scores
the same validation worlds (the training seed plus the validation offset, every camera and arm pose of each) with
the code as it is, so that a change in how things are found (not in the networks) shows in figures. Prints both
summaries: precision and recall of objects per view at an IoU of 0.5, of furniture parts, and what was missed most.
"""

from __future__ import annotations

import argparse
import sys

from roboscript.detector_training.evaluation import score_views
from roboscript.detector_training.scenes import scene_views
from roboscript.detector_training.train import VALIDATION_OFFSET, summary
from roboscript.perception.detection.detector_model import load_detector_model


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worlds", type=int, default=None, help="validation worlds (default: as training)")
    parser.add_argument("--model", default=None, help="a model file (default: the packaged one)")
    args = parser.parse_args()
    model = load_detector_model(args.model)
    settings = model.info.get("settings", {})
    worlds = args.worlds if args.worlds is not None else int(settings.get("validation_worlds", 16))
    if worlds < 1:
        parser.error(f"--worlds must be 1 or more, got {worlds}")
    seed = int(settings.get("seed", 0)) + VALIDATION_OFFSET
    print(f"when trained ({settings.get('validation_worlds', '?')} worlds):")
    print(model.info.get("validation_summary", "(not recorded)"))
    views = (view for k in range(worlds) for view in scene_views(seed, k))
    print(f"\nnow ({worlds} worlds, seed {seed}):", flush=True)
    print(summary(score_views(model, views)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
