"""Masks grown and shrunk by one pixel."""

import numpy as np

from roboscript.perception.detection.pixel_masks import grown, opened, shrunk


def test_opening_takes_off_a_strip_one_pixel_wide_and_keeps_a_block():
    mask = np.zeros((8, 10), dtype=bool)
    mask[2:6, 2:6] = True  # a block
    mask[4, 6:10] = True  # a strip one pixel wide joined to it
    out = opened(mask)
    assert not out[4, 7:].any()  # the strip, but where it meets the block
    assert out[2:6, 3:5].all() and out[3:5, 2:6].all()  # the block, less its corners (a cross rounds them)
    assert not (out & ~mask).any()


def test_growing_and_shrinking_a_pixel():
    mask = np.zeros((5, 5), dtype=bool)
    mask[2, 2] = True
    assert grown(mask).sum() == 5
    assert not shrunk(mask).any()
    assert shrunk(grown(mask)).sum() == 1
