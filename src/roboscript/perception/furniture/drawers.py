"""A drawer's free inside from what the cameras saw of it: where things put into an open drawer can go.

The frame is on the drawer's front, at the foot of its handle (the estimated joint's point,
:mod:`roboscript.perception.furniture.articulation`), turned so that x points along the opening direction; the inside is
behind the front (x < 0). Across and down it is the drawer's bottom as seen; forward, it reaches the front panel's
inner face, which the panel's top edge shows (the bottom just behind the panel is in its shadow); its top is the
highest of the walls seen, at most the front's top. Along x it reaches back to the cabinet's front only, less a
clearance: the part still inside the carcass may be seen through the gap above the drawer, but cannot be reached
from above.
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.geometry import Transform, quat_from_yaw
from roboscript.perception.base import DRAWER_FRONT_CLEARANCE, ArticulationJoint, Receptacle
from roboscript.perception.detection.furniture_parts import top_face
from roboscript.perception.reconstruction.instances import densest_layer

FRONT_BAND = 0.005  # metres behind the front's plane still taken as the front's own points
PANEL_SEARCH = 0.04  # metres behind the front's plane a front panel's top edge is looked for
EDGE_BAND = 0.004  # metres below the front's top still on its top edge
FLOOR_BAND = 0.01  # metres above the lowest points inside that still count as the bottom
LAYER = 0.005  # metres: thickness of the layers the carcass's front is looked for in
MIN_BOTTOM_POINTS = 30  # fewer points on the bottom behind the front: it was not seen (closed, or hidden)
MIN_SPREAD = 0.05  # metres the bottom seen must span each way to count as seen
CELL = 0.02  # metres: the grid the bottom's cover is counted on
FACING_UP = 0.7  # least vertical component of the normal of a point on the bottom
FACING_IN = 0.5  # least component across the drawer of the normal of a point on a wall's inner face
MIN_COVER = 0.4  # share of the cells across the bottom's extent its points must fall in (walls give two lines)
MIN_DEPTH = 0.05  # metres: the least height given to the inside (walls not seen)
WALL = 0.02  # metres taken off all round an inside not seen: the tray's walls and floor, and a margin
MIN_TOP_POINTS = 20  # fewer points on the top: it was not seen
TOP_EDGE_RANK = 5  # the top's front edge: its points' 5th foremost (a camera sees the top thinly near its edge, and
# a percentile lands behind the edge there; an inside must not reach back into the carcass)


def opening_frame(joint: ArticulationJoint) -> Transform:
    """The frame at the drawer's front: at the joint's point (the handle's foot on the front's plane), x along
    the opening direction made level, z up."""
    axis = np.asarray(joint.axis, dtype=float).copy()
    axis[2] = 0.0
    if np.linalg.norm(axis) < 1e-6:
        raise ValueError(f"{joint.part!r} opens along {np.round(joint.axis, 3).tolist()}: not a drawer's level axis")
    axis /= np.linalg.norm(axis)
    return Transform(np.asarray(joint.position, dtype=float), quat_from_yaw(math.atan2(axis[1], axis[0])))


def carcass_front(
    carcass_points: np.ndarray, frame: Transform, behind: float, normals: np.ndarray | None = None
) -> float:
    """Where the carcass's front stands along the frame's x, among the places at most ``behind`` metres behind
    the frame: the front edge of its top where the cameras saw the top (given the points' ``normals``), else the
    densest thin layer of its points across that axis (its front frame around the drawers).

    The top first: the frame around the drawers is a few thin strips, and an open drawer's tray, whose back wall
    stands inside the carcass with it, can show more points in one layer than they do."""
    local = frame.inverse().apply(carcass_points)
    if normals is not None:
        edge = _top_front_edge(local, np.asarray(normals, dtype=float) @ frame.rotation)
        if edge is not None and -behind < edge < LAYER:
            return edge
    x = local[:, 0]
    x = x[(x < LAYER) & (x > -behind)]
    if len(x) == 0:
        raise ValueError(
            f"none of the {len(carcass_points)} points of the cabinet lie within {behind} m behind the drawer's front"
        )
    return densest_layer(x, LAYER)[1]


def _top_front_edge(local: np.ndarray, facing: np.ndarray) -> float | None:
    """The front edge (along x) of the highest level face among ``local`` points whose normals, in the same
    frame, are ``facing``; ``None`` where too few points face up there."""
    found = top_face(local[:, 2], facing[:, 2], MIN_TOP_POINTS)
    if found is None:
        return None
    return float(np.sort(local[found[0], 0])[-TOP_EDGE_RANK])


def drawer_receptacle(
    name: str, points: np.ndarray, normals: np.ndarray, frame: Transform, carcass_x: float
) -> Receptacle | None:
    """The free inside of drawer ``name`` from its seen ``points`` and their ``normals`` (world frame; the
    bottom's face up, the walls' do not), in ``frame`` (:func:`opening_frame`), cut
    at ``carcass_x`` (:func:`carcass_front`) plus the clearance fingers need under the panel above; ``None``
    when no bottom was seen behind the front (a closed drawer shows none; an open one may have been hidden by the
    arm)."""
    local = frame.inverse().apply(points)
    behind = local[:, 0] < -FRONT_BAND
    inside = local[behind]
    if len(inside) < MIN_BOTTOM_POINTS:
        return None
    facing = (np.asarray(normals, dtype=float) @ frame.rotation)[behind]  # in the frame
    up = facing[:, 2] > FACING_UP
    if up.sum() < MIN_BOTTOM_POINTS:
        return None
    floor = _densest_layer(inside[up, 2])  # the bottom is level: its up-facing points crowd one thin layer
    on_floor = np.abs(inside[:, 2] - floor) < FLOOR_BAND / 2
    bottom = inside[on_floor & up]
    if len(bottom) < MIN_BOTTOM_POINTS or np.any(np.ptp(bottom[:, :2], axis=0) < MIN_SPREAD):
        return None
    if _cover(bottom[:, :2]) < MIN_COVER:
        return None
    back = max(float(np.percentile(bottom[:, 0], 1)), carcass_x + DRAWER_FRONT_CLEARANCE)
    front, front_top = _front_panel(local)
    if front is None:
        front = float(np.percentile(bottom[:, 0], 99))
    # The walls' inner faces meet the floor where the inside ends; their outer faces reach its height too, but face
    # away from the middle. Near a wall, its shadow leaves the bottom thinly seen: the outermost half percent.
    middle = float(np.median(bottom[:, 1]))
    inward = on_floor & (np.abs(facing[:, 1]) > FACING_IN) & (facing[:, 1] * (middle - inside[:, 1]) > 0)
    across = np.concatenate([bottom[:, 1], inside[inward, 1]])
    left, right = (float(v) for v in np.percentile(across, [0.5, 99.5]))
    top = float(np.percentile(inside[:, 2], 99))
    if front_top is not None:
        top = min(top, front_top)
    top = max(top, floor + MIN_DEPTH)
    return Receptacle(name, frame, np.array([back, left, floor]), np.array([max(front, back), right, top]))


def unseen_inside(name: str, points: np.ndarray, frame: Transform, carcass_x: float) -> Receptacle:
    """The inside of a drawer pulled out (its front stands ``-carcass_x`` metres before the carcass) whose bottom
    no camera saw (the arm that pulled it stood in the way): from the front panel back to the carcass, across the
    front and from its lower edge up, less :data:`WALL` all round, for the walls and the floor not seen."""
    local = frame.inverse().apply(points)
    front = local[local[:, 0] > -PANEL_SEARCH]
    left, right = (float(v) for v in np.percentile(front[:, 1], [1, 99]))
    low, high = (float(v) for v in np.percentile(front[:, 2], [1, 99]))
    back = carcass_x + DRAWER_FRONT_CLEARANCE
    lower = np.array([back, left + WALL, low + WALL])
    upper = np.array([-WALL, right - WALL, max(high, low + WALL + MIN_DEPTH)])
    return Receptacle(name, frame, lower, np.maximum(upper, lower))


def closed_drawer(name: str, points: np.ndarray, frame: Transform) -> Receptacle:
    """The inside of a drawer that shows none: no depth, across its front as seen."""
    local = frame.inverse().apply(points)
    left, right = (float(v) for v in np.percentile(local[:, 1], [1, 99]))
    low, high = (float(v) for v in np.percentile(local[:, 2], [1, 99]))
    return Receptacle(name, frame, np.array([0.0, left, low]), np.array([0.0, right, high]))


def _front_panel(local: np.ndarray) -> tuple[float | None, float | None]:
    """``(inner face, top)`` of the front panel in the frame: its top edge is the highest layer of points just
    behind the front's plane, and runs back to the inner face; ``None`` where too few points show it."""
    near = local[(local[:, 0] > -PANEL_SEARCH) & (local[:, 0] < FRONT_BAND)]
    if len(near) < 10:
        return None, None
    top = float(np.percentile(near[:, 2], 99))
    edge = near[near[:, 2] > top - EDGE_BAND]
    inner = float(np.percentile(edge[:, 0], 1)) if len(edge) >= 10 else None
    if inner is not None and inner > -FRONT_BAND:  # only the face's top row: the edge itself was not seen
        inner = None
    return inner, top


def _cover(xy: np.ndarray) -> float:
    """The share of the :data:`CELL` grid over the points' extent that holds at least one of them."""
    lower, upper = np.percentile(xy, 1, axis=0), np.percentile(xy, 99, axis=0)
    shape = np.maximum(np.ceil((upper - lower) / CELL).astype(int), 1)
    cells = np.clip(((xy - lower) / CELL).astype(int), 0, shape - 1)
    return len(np.unique(cells[:, 0] * shape[1] + cells[:, 1])) / float(np.prod(shape))


def _densest_layer(heights: np.ndarray) -> float:
    """The median of the thin layer of ``heights`` holding the most of them."""
    lower, upper = densest_layer(heights, LAYER)
    return float(np.median(heights[(heights >= lower) & (heights <= upper)]))
