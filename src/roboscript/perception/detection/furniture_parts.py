"""Which of a view's furniture pixels belong to which part: the carcass, each row's drawer or door, each handle.

The detector tells furniture and handles from everything else; which part a pixel is, it tells from geometry and
from what the description says of the rows (how many, drawer or door, from the top down). Rows are horizontal
bands: each row's handle sits at its middle height, so the handles seen place the bands, and where none is seen
the bands divide the height from the table to the carcass's top evenly. The carcass's front is the plane its top's
front edge lies in; the handles say which way it faces (the fronts around them face that way). A pixel of a band
at or in front of that plane is the row's moving part (its front, and what a pulled drawer or an opened door shows
of itself). The carcass is the whole piece, as a box around its parts.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

LEVEL = 0.9  # normals with z at least this face up (the carcass's top)
UPRIGHT = 0.3  # normals with |z| below this belong to upright faces (fronts)
# Metres below the highest furniture points that are still its top. Within 2 cm lies the top edge of the top
# drawer's front (a 1.5 cm panel above it): pulled out, it was taken for the top's front edge, and every front
# below counted as standing behind the carcass's front (none of them was seen).
TOP_BAND = 0.01
NEAR_HANDLE = (0.1, 0.05)  # metres across and up from a handle within which the front around it lies
FACES_HANDLE = 0.01  # metres the handle stands at least before a face around it that is its front
FRONT_SLACK = 0.01  # metres behind the carcass's front plane that still count as a moving part's
FRONT_SHARE = 0.92  # of a row's height, what its front covers (the rest: the panel between it and the next)
ROW_SLACK = 0.005  # metres beyond its front's height range that a row's part may still show (the handles' spread)


def top_face(heights: np.ndarray, normal_z: np.ndarray, least: int) -> tuple[np.ndarray, float] | None:
    """Which of a carcass's points (their ``heights`` and their normals' vertical parts ``normal_z``) lie on its
    top, the highest level face (within :data:`TOP_BAND` of the 99th percentile of those facing up), and that
    face's height; ``None`` where fewer than ``least`` points face up, or lie on it."""
    up = np.nan_to_num(normal_z) > LEVEL
    if up.sum() < least:
        return None
    height = float(np.percentile(heights[up], 99))
    on_top = up & (heights > height - TOP_BAND)
    if on_top.sum() < least:
        return None
    return on_top, height


@dataclass(frozen=True)
class FurnitureRows:
    """A piece of furniture as the description gives it: its name and its rows' kinds from the top down
    (``drawer`` or ``door``)."""

    name: str
    rows: tuple[str, ...]

    def part_names(self) -> list[tuple[str, str]]:
        """Per row, its moving part's name and its handle's (drawers and doors are numbered apart, handles by
        row), as the tool API names them."""
        out, counts = [], {"drawer": 0, "door": 0}
        for k, kind in enumerate(self.rows):
            out.append((f"{self.name}.{kind}_{counts[kind]}", f"{self.name}.handle_{k}"))
            counts[kind] += 1
        return out


def split_furniture(
    points: np.ndarray,
    normals: np.ndarray,
    handles: Sequence[np.ndarray],
    table: float,
    furniture: FurnitureRows,
) -> dict[str, np.ndarray]:
    """Each part's share of a view's furniture: ``points`` and ``normals`` (n, 3) are the furniture's pixels
    (handles not among them), ``handles`` the points of each handle seen. Returns, by part name, indices into
    ``points`` (all of them under the furniture's own name) and, for handles, indices into ``handles`` (the pieces
    of one row's handle)."""
    out: dict[str, np.ndarray] = {}
    if len(points) == 0:
        return out
    top = float(np.nanpercentile(points[:, 2], 99))
    rows = len(furniture.rows)
    pitch = max(top - table, 1e-3) / rows
    names = furniture.part_names()
    heights = [float(np.median(h[:, 2])) for h in handles]
    row_of = [int(np.clip(np.round((top - z) / pitch - 0.5), 0, rows - 1)) for z in heights]
    for k in sorted(set(row_of)):
        out[names[k][1]] = np.array([j for j, r in enumerate(row_of) if r == k])
    facing = _front_direction(points, normals, handles)
    if facing is None:  # no handle seen: the parts cannot be told apart here
        out[furniture.name] = np.arange(len(points))
        return out
    front = _carcass_front(points, normals, facing, top)
    centres = _row_centres(heights, row_of, top, pitch, rows)
    spacing = float(np.median(-np.diff(centres))) if rows > 1 else pitch
    edges = (centres[:-1] + centres[1:]) / 2  # descending
    band = np.searchsorted(-edges, -points[:, 2])  # 0 for the top row
    # A front fills its row but for the panels between rows: what lies beyond it is the carcass's.
    band[np.abs(points[:, 2] - centres[np.minimum(band, rows - 1)]) > FRONT_SHARE * spacing / 2] = -1
    on_top = (np.nan_to_num(normals[:, 2]) > LEVEL) & (points[:, 2] > top - TOP_BAND)
    moving = (points @ facing > front - FRONT_SLACK) & ~on_top
    for k, (part, _) in enumerate(names):
        mine = np.flatnonzero(moving & (band == k))
        if mine.size:
            out[part] = mine
    # The carcass stands around its fronts: its box is the whole piece's (the pipeline gives what the parts' smaller
    # boxes share with it to the parts).
    out[furniture.name] = np.arange(len(points))
    return out


def _front_direction(points: np.ndarray, normals: np.ndarray, handles: Sequence[np.ndarray]) -> np.ndarray | None:
    """The horizontal direction the fronts face: the normals of the upright faces around the handles that face
    their handle (a handle stands out of its front; a cabinet's side beside a door's handle faces away from it)."""
    found = []
    upright = np.abs(np.nan_to_num(normals[:, 2], nan=1.0)) < UPRIGHT
    for h in handles:
        centre = np.median(h, axis=0)
        across = np.linalg.norm(points[:, :2] - centre[:2], axis=1)
        facing = np.nan_to_num(np.einsum("ij,ij->i", centre - points, normals)) > FACES_HANDLE
        near = upright & facing & (across < NEAR_HANDLE[0]) & (np.abs(points[:, 2] - centre[2]) < NEAR_HANDLE[1])
        if near.sum() >= 10:
            found.append(normals[near])
    if not found:
        return None
    n = np.median(np.concatenate(found), axis=0)
    n[2] = 0.0
    length = np.linalg.norm(n)
    return n / length if length > 1e-6 else None


def _carcass_front(points: np.ndarray, normals: np.ndarray, facing: np.ndarray, top: float) -> float:
    """Where along ``facing`` the carcass's front plane lies: its top's front edge; without a top seen, the
    rearmost of the upright faces that face forward (a closed front)."""
    along = points @ facing
    on_top = (np.nan_to_num(normals[:, 2]) > LEVEL) & (points[:, 2] > top - TOP_BAND)
    if on_top.sum() >= 20:
        return float(np.percentile(along[on_top], 99))
    forward = np.nan_to_num(normals @ facing) > 0.9
    if forward.sum() >= 20:
        return float(np.percentile(along[forward], 5))
    return float(np.percentile(along, 95))


def _row_centres(heights: list[float], row_of: list[int], top: float, pitch: float, rows: int) -> np.ndarray:
    """Each row's middle height, from the top row down: where handles were seen, a line fitted to them, else an
    even division of the height."""
    k = np.arange(rows, dtype=float)
    if len(set(row_of)) >= 2:
        slope, offset = np.polyfit(np.array(row_of, dtype=float), np.array(heights), 1)
        return offset + slope * k
    if row_of:
        return heights[0] - (k - row_of[0]) * pitch
    return top - (k + 0.5) * pitch


def row_bands(handle_heights: dict[int, float], rows: int, top: float, table: float) -> list[tuple[float, float]]:
    """Each row's height range, from the top row down: what its front covers, with :data:`ROW_SLACK` each way.
    ``handle_heights``: the heights of the handles seen, by row (a handle sits at its row's middle height); rows
    where none was seen are placed by :func:`_row_centres`."""
    pitch = max(top - table, 1e-3) / rows
    seen = sorted(handle_heights)
    centres = _row_centres([handle_heights[k] for k in seen], seen, top, pitch, rows)
    spacing = float(np.median(-np.diff(centres))) if rows > 1 else pitch
    half = FRONT_SHARE * spacing / 2 + ROW_SLACK
    return [(float(c - half), float(c + half)) for c in centres]
