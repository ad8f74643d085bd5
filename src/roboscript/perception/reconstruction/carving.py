"""Space a camera sees through is free: the fill under an object's seen surfaces, carved by the views.

An object in the planning scene is solid below the surfaces the cameras saw from above
(:func:`~roboscript.planning.perceived_scene.filled_below`), since its sides and underside are mostly out of sight.
Under an overhang that fill is wrong: a footed bowl's rim, filled down to the table, walls in a cube standing
beside the bowl's foot, and no side grasp of the cube is left. A camera that sees the table through the gap under
the rim says that the gap is empty. A fill point is free where a view's depth image shows a surface clearly
beyond it; the fill within :data:`SHELL` below a seen surface stays whatever the views say, since the pixels at an
object's outline mix it with what lies behind it (the edge of a banana, carved without that shell, was struck by
the arm). A view judges an object only where it shows the object where its points are: an object carried since
that look is not where the view saw it, and the view would see through all of it.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.perception.reconstruction.matching import pixel_depths
from roboscript.robot_io import CameraFrame

SHELL = 0.02  # metres below an object's lowest seen point in a column within which the fill is always kept
BEYOND = 0.02  # metres a view's surface must lie beyond a fill point for the point to count as seen through
SEEN_AGAIN = 0.01  # metres within which a view's surface is the object's own point seen again
LEAST_AGREEMENT = 0.9  # share of the object's points a view shows where they are (or hides) for it to judge


def seen_through(
    fill: np.ndarray,
    surface: np.ndarray,
    frames: Sequence[CameraFrame],
    hidden: Sequence[np.ndarray | None],
) -> np.ndarray:
    """Which ``fill`` points (N, 3) a view of ``frames`` sees through: its depth lies more than :data:`BEYOND`
    beyond them. Only views that show the object's seen ``surface`` points where they are count (at least
    :data:`LEAST_AGREEMENT` of those in the image seen again or hidden behind something nearer); ``hidden`` holds,
    per view, a mask of the pixels that show the robot (or None), which say nothing about what is behind them."""
    fill = np.asarray(fill, dtype=float).reshape(-1, 3)
    free = np.zeros(len(fill), dtype=bool)
    if len(fill) == 0:
        return free
    for frame, mask in zip(frames, hidden, strict=True):
        if frame.depth is None or not _shows_where_it_is(surface, frame, mask):
            continue
        depth, z, informative = pixel_depths(fill, frame, mask)
        free |= informative & (depth > z + BEYOND)
    return free


def _shows_where_it_is(surface: np.ndarray, frame: CameraFrame, mask: np.ndarray | None) -> bool:
    depth, z, informative = pixel_depths(surface, frame, mask)
    if not informative.any():
        return False
    through = informative & (depth > z + SEEN_AGAIN)
    return 1.0 - np.count_nonzero(through) / np.count_nonzero(informative) >= LEAST_AGREEMENT
