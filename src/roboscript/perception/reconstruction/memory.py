"""Occupancy memory across looks: space the robot's own body hides from every camera is not free space.

Each look sees only what is in front of the cameras; when the arm hangs over a drawer it has just filled, the
drawer's walls behind the arm are missing from that look, and a planning scene built from it alone would let the
fingers through them. A surface point from an earlier look is kept unless a camera now sees through it (its pixel
shows a surface farther away, so the point has gone) or sees it again (the new look has it already).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.perception.reconstruction.matching import VISIBILITY_TOLERANCE, pixel_depths
from roboscript.robot_io import CameraFrame


def remembered(
    old: np.ndarray,
    frames: Sequence[CameraFrame],
    hidden: Sequence[np.ndarray | None],
    tolerance: float = VISIBILITY_TOLERANCE,
) -> np.ndarray:
    """The points of ``old`` that no view of ``frames`` sees through or sees again. ``hidden`` holds, per view, a
    mask of the pixels that show the robot (or None): those pixels say nothing about what is behind them."""
    old = np.asarray(old, dtype=float).reshape(-1, 3)
    if len(old) == 0:
        return old
    kept = old
    for frame, mask in zip(frames, hidden, strict=True):
        if len(kept) == 0:
            break
        if frame.depth is None or not np.isfinite(frame.depth).any():
            continue
        # Only what the views before kept is projected: the first view drops most of a scene seen again.
        depth, z, informative = pixel_depths(kept, frame, mask)
        kept = kept[~(informative & (depth > z - tolerance))]  # seen through, or seen again
    return kept
