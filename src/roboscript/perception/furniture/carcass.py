"""A cabinet's carcass as the solid it is: its side and back panels, from the parts of it the cameras saw.

Cameras see a cabinet's top, its front and the insides its open doors show, but often not its outer sides or its
back: a camera on the left sees the left side only at a grazing angle, and none sees the back. Left as seen, the
planning scene has the cabinet's top standing on nothing at its sides, and a thing carried past it (a wooden bar held
by its end, sticking out ahead of the hand) is planned straight through the side panel. A carcass has panels at its
sides and back whether or not they were seen: they are laid, :data:`PANEL` thick, inside the faces of the box its
seen points fill in the cabinet's own frame (x out of its front, which the drawers' joints or a door's compartment
tell). Its front is its top's front edge, seen from above: an open drawer's tray, whose points go with the
carcass's, stands out of its front and would carry the side panels out with it, into the arm's way.
"""

from __future__ import annotations

import logging

import numpy as np

from roboscript.errors import RoboScriptError
from roboscript.perception.base import Perception
from roboscript.perception.detection.furniture_parts import top_face
from roboscript.perception.furniture.compartments import MIN_TOP_POINTS, PANEL

log = logging.getLogger(__name__)

EDGE = 0.5  # percentile of the points along each axis taken as the carcass's face (a few stray points lie beyond)
SPACING = 0.01  # metres between the points that stand for a panel (finer than the planning scene's voxels)


def carcass_facing(perception: Perception, furniture: str) -> np.ndarray | None:
    """The horizontal direction out of ``furniture``'s front: a drawer's opening direction, else the front of the
    compartment behind a door; None where it has neither, or neither was seen well enough to tell."""
    joints = perception.joints(furniture)
    for joint in joints:
        if joint.type == "prismatic" and np.linalg.norm(joint.axis[:2]) > 0.5:
            return np.array([joint.axis[0], joint.axis[1], 0.0]) / np.linalg.norm(joint.axis[:2])
    for joint in joints:
        try:
            inside = perception.receptacle(joint.part) if joint.type == "revolute" else None
        except RoboScriptError as error:  # too little of it seen: its panels are left as seen
            log.debug("no front for %s's carcass from %s: %s", furniture, joint.part, error)
            continue
        if inside is not None:
            return inside.frame.rotation[:, 0].copy()
    return None


def carcass_frame(facing: np.ndarray) -> np.ndarray:
    """The rotation (columns: out of the front, to the left seen from the front, up) of a carcass facing
    ``facing`` (a horizontal direction; its vertical part is dropped)."""
    out = np.array([facing[0], facing[1], 0.0], dtype=float)
    length = float(np.linalg.norm(out))
    if length < 1e-6:
        raise ValueError(f"a carcass's front must face a horizontal direction, got {list(facing)}")
    out /= length
    up = np.array([0.0, 0.0, 1.0])
    return np.column_stack([out, np.cross(up, out), up])


def carcass_panels(
    points: np.ndarray, normals: np.ndarray, facing: np.ndarray, spacing: float = SPACING
) -> np.ndarray:
    """Points (N, 3) filling the side and back panels of the carcass whose seen surface is ``points`` (M, 3) with
    outward ``normals`` and whose front faces ``facing``: each panel :data:`PANEL` thick inside the faces of the
    box the points fill along the carcass's own axes, from the lowest seen point up to the top, and no further
    forward than the top's front edge. Empty where the top was seen too little to tell its edges."""
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    normals = np.asarray(normals, dtype=float).reshape(-1, 3)
    found = top_face(points[:, 2], normals[:, 2], MIN_TOP_POINTS)
    if found is None:
        return np.zeros((0, 3))
    top, top_height = found
    rotation = carcass_frame(facing)
    local = points @ rotation
    # Its sides and back as far as any of its points go (the top's edges are seen thinly); its front where its
    # top's front edge is.
    lower = np.percentile(local, EDGE, axis=0)
    upper = np.percentile(local, 100 - EDGE, axis=0)
    upper[0] = float(np.percentile(local[top, 0], 100 - EDGE))
    lower[2], upper[2] = float(points[:, 2].min()), top_height
    panels = [
        (np.array([lower[0], lower[1], lower[2]]), np.array([upper[0], lower[1] + PANEL, upper[2]])),  # one side
        (np.array([lower[0], upper[1] - PANEL, lower[2]]), np.array([upper[0], upper[1], upper[2]])),  # the other
        (np.array([lower[0], lower[1], lower[2]]), np.array([lower[0] + PANEL, upper[1], upper[2]])),  # the back
    ]
    filled = [_grid(low, high, spacing) for low, high in panels if np.all(high > low)]
    if not filled:
        return np.zeros((0, 3))
    return np.vstack(filled) @ rotation.T


def _grid(lower: np.ndarray, upper: np.ndarray, spacing: float) -> np.ndarray:
    """Points spread through the box ``[lower, upper]``, its faces included, at most ``spacing`` apart."""
    counts = np.maximum(2, np.ceil((upper - lower) / spacing).astype(int) + 1)
    axes = [np.linspace(low, high, n) for low, high, n in zip(lower, upper, counts, strict=True)]
    return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)
