"""Occupancy boxes from points: an exact, disjoint cover of the occupied voxels, each box tight on its points."""

from __future__ import annotations

import numpy as np
import pytest

from roboscript.planning.occupancy import THICKNESS, RememberedBoxes, merge_voxels, occupied_boxes, occupied_voxels


def _cover(boxes) -> list[tuple[int, int, int]]:
    return [
        (i, j, k)
        for first, last in boxes
        for i in range(first[0], last[0] + 1)
        for j in range(first[1], last[1] + 1)
        for k in range(first[2], last[2] + 1)
    ]


def test_merged_boxes_cover_the_occupied_voxels_exactly_once():
    rng = np.random.default_rng(3)
    cells = {tuple(int(v) for v in c) for c in rng.integers(0, 6, size=(120, 3))}
    covered = _cover(merge_voxels(cells))
    assert len(covered) == len(set(covered))  # disjoint
    assert set(covered) == cells  # exact


def test_a_flat_sheet_becomes_one_box():
    cells = {(i, j, 4) for i in range(10) for j in range(7)}
    assert len(merge_voxels(cells)) == 1


def test_a_table_with_a_box_on_it_keeps_the_table_top_where_it_was_seen():
    rng = np.random.default_rng(0)
    table = np.column_stack([rng.uniform(-0.5, 0.5, 40000), rng.uniform(-0.4, 0.4, 40000), np.full(40000, 0.82)])
    box = rng.uniform(0.0, 0.1, (8000, 3)) + np.array([0.1, 0.1, 0.82])
    boxes = occupied_boxes(np.vstack([table, box]))
    away = [b for b in boxes if b.upper[0] < 0.05 or b.lower[0] > 0.25]  # table away from the box
    assert away and all(abs(b.upper[2] - 0.82) < 1e-9 and b.lower[2] < 0.82 - THICKNESS / 2 for b in away)
    assert len(boxes) < 100  # merged, not one box per voxel (there are over 900)
    points = np.vstack([table, box])[::50]
    inside = [np.any([np.all((p >= b.lower - 1e-9) & (p <= b.upper + 1e-9)) for b in boxes]) for p in points]
    assert all(inside)  # every point is in a box


def test_bad_sizes_are_refused():
    with pytest.raises(ValueError, match="voxel must be a positive size in metres, got 0"):
        occupied_voxels(np.zeros((3, 3)), 0)
    with pytest.raises(ValueError, match="thickness must be >= 0 metres"):
        occupied_boxes(np.zeros((3, 3)), thickness=-1)
    assert occupied_boxes(np.zeros((0, 3))) == []


def test_cells_are_found_as_numpys_unique_rows_finds_them_in_the_same_order():
    from roboscript.planning.occupancy import unique_cells

    rng = np.random.default_rng(3)
    for cells in (
        rng.integers(-40, 60, size=(5000, 3)),
        np.array([[7, -2, 3]]),
        np.array([[0, 0, 0], [0, 0, 0], [-1, 5, 2]]),
        np.array([[-(2**40), 0, 0], [2**40, 1, 1], [0, 2**30, 5]]),  # too wide to pack: the rows themselves
        rng.integers(-9, 9, size=(300, 2)),  # columns of a plane
    ):
        expected, inverse = np.unique(cells, axis=0, return_inverse=True)
        found, found_inverse = unique_cells(cells.astype(np.int64))
        assert np.array_equal(found, expected) and np.array_equal(found_inverse, inverse.reshape(-1))


def _corners(boxes) -> list:
    return [(b.lower.tolist(), b.upper.tolist()) for b in boxes]


def test_remembered_boxes_answer_as_occupied_boxes_and_keep_only_the_last_scenes():
    rng = np.random.default_rng(0)
    table, block = rng.uniform([0, 0, 0], [0.3, 0.3, 0.001], (500, 3)), rng.uniform([0.1] * 3, [0.15] * 3, (200, 3))
    remembered = RememberedBoxes()
    first = remembered.boxes(table)
    assert _corners(first) == _corners(occupied_boxes(table)) and remembered.hits == 0
    assert _corners(remembered.boxes(block, 0.01)) == _corners(occupied_boxes(block, 0.01))
    remembered.next_scene()
    assert remembered.boxes(table.copy()) is first and remembered.hits == 1  # the same points, not the same array
    assert _corners(remembered.boxes(table, 0.01)) == _corners(occupied_boxes(table, 0.01))  # another voxel size
    assert remembered.hits == 1
    remembered.next_scene()  # the block was not in that scene: forgotten
    remembered.boxes(block, 0.01)
    assert remembered.hits == 1
