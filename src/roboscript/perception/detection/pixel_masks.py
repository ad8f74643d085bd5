"""Boolean image masks grown and shrunk by one pixel (a 3x3 cross), without an image library."""

from __future__ import annotations

import numpy as np


def grown(mask: np.ndarray) -> np.ndarray:
    """``mask`` grown by one pixel in each of the four directions."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    out[:, 1:] |= mask[:, :-1]
    out[:, :-1] |= mask[:, 1:]
    return out


def shrunk(mask: np.ndarray) -> np.ndarray:
    """``mask`` less every pixel one of whose four neighbours in the image is outside it."""
    out = mask.copy()
    out[1:] &= mask[:-1]
    out[:-1] &= mask[1:]
    out[:, 1:] &= mask[:, :-1]
    out[:, :-1] &= mask[:, 1:]
    return out


def opened(mask: np.ndarray) -> np.ndarray:
    """``mask`` shrunk then grown: strips one pixel wide are gone, the rest keeps its outline."""
    return grown(shrunk(mask))
