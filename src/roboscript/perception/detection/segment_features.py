"""What a segment looks like, as numbers a classifier can tell object types apart by: its size and shape in 3D
(height above the table, extent across, where its points are by height, which way its surfaces face), how much of
its box in the image it fills (round things less than boxes), and its colours (the mean, the mean of its faces that
look up and of those that stand upright: a can's top and side, a mug's inside and outside, and a coarse histogram
that survives shading)."""

from __future__ import annotations

import numpy as np

from roboscript.perception.detection.piece_pairs import horizontal_extent
from roboscript.perception.detection.segments import FramePoints

COLOUR_LEVELS = 4  # per channel, for the colour histogram
PROFILE_BINS = 4  # of the height profile
SEGMENT_FEATURES = 26 + COLOUR_LEVELS**3 + PROFILE_BINS
RISE, EXTENT = 5, 6  # the columns of a segment's rise (metres from its lowest to its highest) and its longest extent


def segment_features(
    points: np.ndarray,
    colours: np.ndarray,
    normals: np.ndarray,
    pixel_size: np.ndarray,
    table: float,
    fill: float = 1.0,
) -> np.ndarray:
    """:data:`SEGMENT_FEATURES` numbers for one segment: ``points`` (n, 3) world, ``colours`` (n, 3) 0-255,
    ``normals`` (n, 3) (NaN allowed), ``pixel_size`` (n,) metres, ``table`` the table's height, ``fill`` the share
    of its image box its pixels cover."""
    n = len(points)
    z = points[:, 2] - table
    low, mid, high = np.percentile(z, [2, 50, 98])
    extent = horizontal_extent(points[:, :2])
    c = colours / 255.0
    mean = c.mean(axis=0)
    brightness = c.sum(axis=1) + 1e-6
    chroma = (c[:, :2] / brightness[:, None]).mean(axis=0)
    levels = np.minimum((c * COLOUR_LEVELS).astype(int), COLOUR_LEVELS - 1)
    bins = (levels[:, 0] * COLOUR_LEVELS + levels[:, 1]) * COLOUR_LEVELS + levels[:, 2]
    histogram = np.bincount(bins, minlength=COLOUR_LEVELS**3) / n
    nz = np.abs(np.nan_to_num(normals[:, 2]))
    rise = max(high - low, 1e-3)
    profile = np.histogram(np.clip((z - low) / rise, 0, 0.999), bins=PROFILE_BINS, range=(0, 1))[0] / n
    area = float(np.sum(pixel_size**2))
    up, upright = nz > 0.9, nz < 0.3
    top_colour = c[up].mean(axis=0) if up.any() else mean
    side_colour = c[upright].mean(axis=0) if upright.any() else mean
    out = np.concatenate(
        [
            [np.log(n), np.log(area + 1e-8), low, mid, high, high - low, *extent, extent[0] * extent[1]],
            mean,
            c.std(axis=0),
            chroma,
            [np.mean(up), np.mean(upright), fill],
            top_colour,
            side_colour,
            histogram,
            profile,
        ]
    )
    return out


def features_of_pixels(fp: FramePoints, pixels: np.ndarray, table: float) -> np.ndarray:
    """:func:`segment_features` of the working pixels ``pixels`` (flat indices) of ``fp``."""
    width = fp.points.shape[1]
    rows, cols = pixels // width, pixels % width
    box = (np.ptp(rows) + 1) * (np.ptp(cols) + 1)
    return segment_features(
        fp.points.reshape(-1, 3)[pixels],
        fp.colours.reshape(-1, 3)[pixels],
        fp.normals.reshape(-1, 3)[pixels],
        fp.pixel_size.ravel()[pixels],
        table,
        len(pixels) / box,
    )
