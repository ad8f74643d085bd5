"""Whether a look shows a place empty: the cameras see through where something stood.

A detector may put an object's name on something else (a white mug's box on an open drawer's front), and the object
may be missed where it really stands (the arm in front of it). A find far from where an untouched object was is
then believed only where the look sees through the object's old place: its depth images measure surfaces beyond the
points seen there before. Where the old place shows the same surfaces, or is hidden (by the arm, by things in front),
the object is taken to be still there.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from roboscript.perception.reconstruction.matching import project
from roboscript.robot_io import CameraFrame

THROUGH = 0.02  # metres beyond a point the depth image must measure for a view to see through it
GONE_SHARE = 0.5  # the share of a place's points a look must see through (of those it can tell) for it to be empty
MIN_TOLD = 20  # points a look must tell about (seen or seen through) to say anything of a place


def seen_through(
    points: np.ndarray, frames: Sequence[CameraFrame], masks: Sequence[np.ndarray | None]
) -> tuple[np.ndarray, np.ndarray]:
    """Per point, whether some view sees through it (its depth is :data:`THROUGH` beyond the point) and whether
    some view sees it (its depth is at the point). Pixels of the robot (``masks``, one per frame or None) tell
    nothing; a surface in front of a point hides it and tells nothing either."""
    through = np.zeros(len(points), dtype=bool)
    seen = np.zeros(len(points), dtype=bool)
    for frame, mask in zip(frames, masks, strict=True):
        view = project(points, frame)
        inside = view.u >= 0
        depth = np.zeros(len(points))
        depth[inside] = frame.depth[view.v[inside], view.u[inside]]
        told = inside & (depth > 0)
        if mask is not None:
            told[inside] &= ~mask[view.v[inside], view.u[inside]]
        through |= told & (depth > view.z + THROUGH)
        seen |= told & (np.abs(depth - view.z) <= THROUGH)
    return through, seen


def stands_empty(points: np.ndarray, frames: Sequence[CameraFrame], masks: Sequence[np.ndarray | None]) -> bool:
    """Whether the look of ``frames`` shows the place ``points`` covered empty: it sees through at least
    :data:`GONE_SHARE` of the points it can tell about, and it can tell about at least :data:`MIN_TOLD`. A point one
    view sees and another sees through counts as seen: an edge's point falls on the background beside it."""
    through, seen = seen_through(points, frames, masks)
    gone = int(np.count_nonzero(through & ~seen))
    told = gone + int(np.count_nonzero(seen))
    return told >= MIN_TOLD and gone >= GONE_SHARE * told
