"""Grasps from an object's box: the central lift (top-down) grasp and the horizontal grasp.

Each returns candidate TCP poses, best first; the tool layer keeps the first one the arm can reach. A gripper pose's
z axis is its approach direction and its y axis the direction in which the fingers close.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from roboscript.errors import FailureError
from roboscript.geometry import Transform
from roboscript.names import kind_of
from roboscript.perception.base import Perception

DOWN = np.array([0.0, 0.0, -1.0])
# A handle grasp aims this far in from the handle's outer surface: the middle of its bar.
HANDLE_BAR_RADIUS = 0.008


class GraspError(FailureError, ValueError):
    """No grasp of the asked kind suits this object; the message says why and what to try instead."""


def _frame(closing: np.ndarray, approach: np.ndarray, outward: np.ndarray) -> np.ndarray:
    """Rotation [x, y, z] with z = approach and y = ±closing, the sign chosen so that x points along ``outward``
    (away from the robot), which keeps the wrist near the middle of its range."""
    y = closing / np.linalg.norm(closing)
    z = approach / np.linalg.norm(approach)
    x = np.cross(y, z)
    if x @ outward < 0:
        y, x = -y, -x
    return np.column_stack([x, y, z])


def central_lift_grasps(
    perception: Perception,
    name: str,
    description: str,
    max_width: float,
    base_xy: np.ndarray,
    finger_reach: float | None = None,
) -> list[Transform]:
    """Top-down grasps at the centre of the object's box, closing across its narrower side.

    ``description`` is "top" (the TCP 3 cm below the top, or at mid height if the object is lower than 6 cm) or
    "center" (at mid height). Either way the TCP goes no deeper below the object's top than the fingers reach
    (``finger_reach``: from the TCP back to the hand, less a margin): on a tall box, mid height would put the hand
    itself onto the box's top, so the grasp takes the box as low as the fingers allow.
    """
    if description not in ("top", "center"):
        raise ValueError(f"description must be 'top' or 'center', got {description!r}")
    box = perception.box(name)
    center_xy, yaw, half = perception.footprint(name)
    z = box.center[2] if description == "center" else max(box.center[2], box.upper[2] - 0.03)
    if finger_reach is not None:
        z = max(z, box.upper[2] - max(finger_reach - HAND_CLEARANCE, 0.0))
    axes = [np.array([math.cos(yaw), math.sin(yaw), 0.0]), np.array([-math.sin(yaw), math.cos(yaw), 0.0])]
    order = np.argsort(half)  # close across the narrow side first
    outward = np.append(center_xy - base_xy, 0.0)
    outward = outward / (np.linalg.norm(outward) + 1e-9)
    candidates = []
    # Shallower grasps follow the one asked for: where the hand would meet what stands round the object at that
    # depth (a block in a bowl, the hand on its rim), a grasp nearer the top still holds it; where the fingertips
    # would meet what a low object lies on (a gelatin box on a plate's floor), one with the pads' top at its top.
    shallower = (box.upper[2] - 0.03, box.upper[2] - SHALLOWEST, box.upper[2] - FINGER_PAD)
    depths = [z] + [d for d in sorted(shallower) if d > z + 0.003]
    for depth in depths:
        for k in order:
            if 2 * half[k] > max_width - 0.003:
                continue
            candidates.append(Transform.from_rotation(np.array([*center_xy, depth]), _frame(axes[k], DOWN, outward)))
    # Then the hand turned off square, where the object is narrow enough that way: fingers closing slantwise turn
    # it square as they close, and the hand's ends swing clear of a neighbour's corner (a Rubik's cube by a
    # basket turned 35 degrees, whose rim stood 5 mm inside the hand's end either square way).
    points = perception.points(name).points
    outline = Outline.of(perception, name, points)
    for depth in depths:
        for k, turn in ((k, turn) for turn in OFF_SQUARE for k in order):
            closing = _turned(axes[k], turn)
            # A round thing is at least as wide any way as its footprint's narrower side: the cameras see its near
            # side only (a tuna can 8.6 cm across, seen 8.1 cm wide slantwise, slipped from the 2F-85's 8.5).
            seen = _extent(points, closing) if len(points) else 0.0
            across = outline.across(closing) if outline.box_like else max(seen, 2 * float(np.min(outline.half)))
            if across <= max_width - 0.003:
                candidates.append(
                    Transform.from_rotation(np.array([*center_xy, depth]), _frame(closing, DOWN, outward))
                )
    if not candidates:
        raise GraspError(
            f"{name!r} is {2 * half.min() * 100:.1f} cm across its narrowest side, wider than the gripper's "
            f"{max_width * 100:.1f} cm opening: no top-down grasp fits; try parse_adaptive_shape_grasp_pose"
        )
    return candidates


def _turned(direction: np.ndarray, angle: float) -> np.ndarray:
    """The horizontal ``direction`` turned ``angle`` radians about the vertical."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([c * direction[0] - s * direction[1], s * direction[0] + c * direction[1], 0.0])


OFF_SQUARE = (math.radians(15), -math.radians(15), math.radians(30), -math.radians(30))
SHALLOWEST = 0.018  # metres below an object's top: the shallowest top-down grasp (fingertip pads are ~2 cm)
FINGER_PAD = 0.01  # metres: half the height of a fingertip pad
RIM_GRIP = 0.02  # metres below a tall object's top where the higher horizontal grip closes (a cup at its rim)
HAND_CLEARANCE = 0.008  # metres kept between an object's top and the hand behind the fingers


# A given approach_direction is a preference: where the arm cannot reach it, approaches turned about the vertical
# by up to 0.8 rad (46 degrees) are tried, nearest first.
PREFERENCE_CONE = (0.0, 0.2, -0.2, 0.4, -0.4, 0.6, -0.6, 0.8, -0.8)
# Objects whose middle is lower than this over their bottom are approached tilted down (radians below level).
LOW_OBJECT = 0.045
LOW_TILTS = (0.5, 0.9, 0.0)
# Turns of the default approach tried, nearest first (radians about world z).
APPROACH_YAWS = (0.0, 0.35, -0.35, 0.7, -0.7, 1.0, -1.0, 1.3, -1.3)
# ... and, where none of those is reachable, the turns beyond them that an arm still reaches round to (a cube
# nearly as wide as the opening, a bowl beside it: only a side-on approach from its far side is free).
FAR_APPROACH_YAWS = (1.6, -1.6, 1.9, -1.9)


# An object whose points fill this much of its footprint rectangle (seen from above) is box-like: a box fills it
# (0.85 to 0.99 as the cameras sample it), a round one at most pi/4 (a bowl 0.75, a cup 0.71, a pear 0.65).
BOX_LIKE_FILL = 0.82


@dataclass(frozen=True)
class Outline:
    """An object's footprint rectangle (``yaw``, ``half`` extents), and whether the object fills it."""

    yaw: float
    half: np.ndarray
    box_like: bool

    @classmethod
    def of(cls, perception: Perception, name: str, points: np.ndarray) -> Outline:
        _, yaw, half = perception.footprint(name)
        half = np.asarray(half, dtype=float)
        area = 4.0 * float(half[0] * half[1])
        try:
            filled = ConvexHull(points[:, :2]).volume / area if len(points) >= 3 and area > 0 else 0.0
        except QhullError:
            filled = 0.0
        return cls(float(yaw), half, filled >= BOX_LIKE_FILL)

    def across(self, direction: np.ndarray) -> float:
        """How wide the rectangle is along the horizontal ``direction``."""
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return 2.0 * float(self.half[0] * abs(direction[0] * c + direction[1] * s)) + 2.0 * float(
            self.half[1] * abs(-direction[0] * s + direction[1] * c)
        )


def _finger_band(points: np.ndarray, height: float, half: float = 0.02) -> np.ndarray:
    """The points at the height the finger pads close over (all of them where that band shows too few)."""
    band = points[np.abs(points[:, 2] - height) < half]
    return band if len(band) >= 10 else points


def _extent(points: np.ndarray, direction: np.ndarray) -> float:
    """How wide the points are along ``direction``: what the fingers must open across when closing along it.
    Measured on what is seen, not on the world-aligned box, which a turned box or a ball overstates."""
    along = points @ direction
    return float(along.max() - along.min())


def _with_side_on_yaws(
    yaws: list[float], approach: np.ndarray, footprint_yaw: float, nearer: float = 0.0
) -> list[float]:
    """The approach turns, with those that come at a turned object square to its sides added (within the range
    tried, beyond ``nearer``): closing across a box's narrow side at an angle would need a wider opening."""
    heading = math.atan2(approach[1], approach[0])
    square = [math.remainder(footprint_yaw + k * math.pi / 2 - heading, 2 * math.pi) for k in range(4)]
    extra = [d for d in square if nearer < abs(d) <= max(abs(y) for y in yaws)]
    return sorted({*yaws, *extra}, key=abs)


def _handle_normal(perception: Perception, name: str, box) -> np.ndarray:
    """The horizontal direction a handle faces: a drawer's opening direction, a door's front's normal beside it,
    or (a handle of nothing known) its own front's normal."""
    joints = perception.joints(name) if kind_of(name) == "handle" else []
    if joints and joints[0].type == "prismatic":
        normal = np.asarray(joints[0].axis, dtype=float).copy()
    elif joints:
        # A bar on standoffs has no face of its own to speak of: the plane its observed points fit faced sideways
        # (a Panda then came at a door's handle along the door's face). The door's front faces the way it does.
        normal = np.asarray(perception.plane_normal(joints[0].part, box.center), dtype=float).copy()
    else:
        normal = np.asarray(perception.plane_normal(name, box.center + np.array([1.0, 0.0, 0.0])), dtype=float).copy()
    normal[2] = 0.0
    return normal / max(float(np.linalg.norm(normal)), 1e-9)


def _swept_width(points: np.ndarray, approach: np.ndarray, closing: np.ndarray, height: float, tilt: float) -> float:
    """How wide the object is, across ``closing``, where fingers coming in tilted ``tilt`` radians down along
    ``approach`` to ``height`` pass it: from that height up to where they cross its near side."""
    if not len(points):
        return 0.0
    top = height + math.tan(tilt) * _extent(points, approach) / 2 + FINGER_PAD
    swept = points[(points[:, 2] > height - FINGER_PAD) & (points[:, 2] < top)]
    return _extent(swept, closing) if len(swept) else 0.0


def _level_grasps(
    box,
    is_handle: bool,
    points: np.ndarray,
    approach: np.ndarray,
    outward_normal: np.ndarray,
    yaws: list[float],
    height: float,
    max_width: float,
    all_points: np.ndarray,
    outline: Outline,
) -> list[Transform]:
    """The horizontal grasps at one ``height`` (for handles, their bar), one per approach yaw that fits: across
    the points at that height (``points``) and, for a grasp tilted down, across all the fingers sweep past on
    their way in (``all_points``: a cup's rim is wider than its body lower down)."""
    size = box.size
    out = []
    # Level with the middle of a low object, the hand (6.6 cm tall across a horizontal closing) would touch its
    # support: such an object is approached from the side tilted downwards, the level approach tried last.
    # Anything else is gripped level first, then tilted down: near the table, a level hand brings the arm's
    # wrist down onto it (a Panda gripping a cup 4.5 cm up), where a tilted one keeps it higher.
    if is_handle:
        tilts: tuple[float, ...] = (0.0,)
    else:
        tilts = LOW_TILTS if height - box.lower[2] < LOW_OBJECT else (0.0, *LOW_TILTS[:-1])
    for tilt, dyaw in ((t, y) for t in tilts for y in yaws):
        c, s = math.cos(dyaw), math.sin(dyaw)
        a = np.array([c * approach[0] - s * approach[1], s * approach[0] + c * approach[1], 0.0])
        if is_handle:
            long_axis = np.eye(3)[int(np.argmax(size))]
            closing = np.cross(a, long_axis)
            if np.linalg.norm(closing) < 1e-6:
                continue
            # Aim at the bar: just inside the handle's outermost surface along the part's opening direction.
            reach = float(np.abs(outward_normal) @ size) / 2
            target = box.center + outward_normal * (reach - HANDLE_BAR_RADIUS)
            up = np.array([0.0, 0.0, 1.0])
            outward = up if abs(closing[2]) < 0.5 else np.cross(up, a)
        else:
            closing = np.cross(np.array([0.0, 0.0, 1.0]), a)
            across = _extent(points, closing) if len(points) else float(np.abs(closing) @ size)
            if outline.box_like:
                # Closing slantwise across a box, the fingers meet its corners, which the cameras sample thinly
                # and not at all behind it: a 10 x 4 cm bar seen 8.1 cm wide at 57 degrees is 8.8 cm.
                across = max(across, outline.across(closing))
            if across > max_width - 0.003 or (
                tilt and _swept_width(all_points, a, closing, height, tilt) > max_width - 0.003
            ):
                continue
            target = np.array([box.center[0], box.center[1], height])
            outward = np.array([0.0, 0.0, -1.0])
            a = math.cos(tilt) * a + math.sin(tilt) * DOWN
        out.append(Transform.from_rotation(target, _frame(closing, a, outward)))
    return out


def horizontal_grasps(
    perception: Perception,
    name: str,
    approach_direction: np.ndarray | None,
    max_width: float,
    base_xy: np.ndarray,
    far: bool = False,
) -> list[Transform]:
    """Grasps approaching horizontally; handles are gripped across their bar, other things across their width.

    Without ``approach_direction`` a handle is approached against its part's opening direction and an object from
    the robot's side; several nearby yaws follow, for the tool layer to pick a reachable one. A given
    ``approach_direction`` is preferred, not demanded: turns of it within :data:`PREFERENCE_CONE` follow it. An
    object too low to be gripped level without the hand touching its support is approached tilted downwards.
    With ``far``, an object's turns beyond those instead (:data:`FAR_APPROACH_YAWS`, side-on ones among them).
    """
    box = perception.box(name)
    is_handle = kind_of(name) == "handle"
    if approach_direction is not None:
        approach = np.asarray(approach_direction, dtype=float).copy()
        approach[2] = 0.0
        if approach.shape != (3,) or np.linalg.norm(approach) < 1e-6:
            raise ValueError(
                "approach_direction must be a 3-vector with a horizontal part, got "
                f"{np.asarray(approach_direction).tolist()}"
            )
        yaws = list(PREFERENCE_CONE)
    else:
        # A handle is approached against its part's opening direction, anything else from the robot's side.
        approach = -_handle_normal(perception, name, box) if is_handle else np.append(box.center[:2] - base_xy, 0.0)
        yaws = list(FAR_APPROACH_YAWS if far else APPROACH_YAWS)
    approach = approach / np.linalg.norm(approach)
    if not is_handle and approach_direction is None:
        nearer = max(APPROACH_YAWS) if far else 0.0
        yaws = _with_side_on_yaws(yaws, approach, perception.footprint(name)[1], nearer)
    outward_normal = -approach if approach_direction is None else _handle_normal(perception, name, box)
    candidates = []
    target_z = min(box.center[2], box.lower[2] + 0.06)
    # Higher grips follow on a tall object: a cup's rim is narrower than its body's widest part, and a hand
    # that grips higher keeps the wrist off the table (a Panda gripping a cup 4.5 cm up met the table with it).
    heights = [target_z] if is_handle else [target_z] + [h for h in (box.upper[2] - RIM_GRIP,) if h > target_z + 0.01]
    all_points = perception.points(name).points if not is_handle else np.zeros((0, 3))
    outline = Outline.of(perception, name, all_points) if not is_handle else Outline(0.0, np.zeros(2), False)
    for height in heights:
        points = _finger_band(all_points, height) if not is_handle else all_points
        candidates += _level_grasps(
            box, is_handle, points, approach, outward_normal, yaws, height, max_width, all_points, outline
        )
    if not candidates:
        raise GraspError(
            f"{name!r} is wider than the gripper's {max_width * 100:.1f} cm opening from every horizontal approach "
            "tried; give another approach_direction or use parse_adaptive_shape_grasp_pose"
        )
    return candidates
