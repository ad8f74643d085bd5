"""An adaptive 6-DoF grasp detector that needs no learned weights.

Antipodal sampling over an object's observed points: a seed point's normal gives a closing line; a point on the
far side of the object along that line whose normal is roughly opposite closes the pair. An open container's rim
adds pairs across its wall (:mod:`roboscript.grasping.rims`). Each pair becomes grasps
with several approach directions perpendicular to its closing axis. Candidates are scored by contact quality (how
well both normals lie inside the friction cone), rejected where the fingers (closing from fully open) or the hand
behind them would hit observed points, and ranked by the caller's preferences (position, approach direction, plane
normal).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from roboscript.geometry import Transform
from roboscript.grasping.rims import rim_pairs
from roboscript.perception.base import ObjectPoints
from roboscript.phases import timed


@dataclass(frozen=True)
class GripperGeometry:
    """Collision proxy of a parallel gripper in the TCP frame (z: approach, y: closing, origin between the tips).

    The fingers are checked over all they sweep while closing from ``max_width`` (the gripper approaches open)
    to the grasp's width; the hand behind them is the box ``hand_lower``..``hand_upper`` (defaults: the Franka
    hand, 21 cm across the closing direction: a hand proxy no wider than the opening let it sink onto a mug's far
    rim)."""

    max_width: float
    finger_length: float = 0.045  # how far the fingers reach back from the TCP to the hand
    tip_length: float = 0.012  # how far the fingertips reach past the TCP along the approach
    finger_thickness: float = 0.012
    finger_breadth: float = 0.02  # along x
    hand_lower: tuple[float, float, float] = (-0.033, -0.105, -0.13)
    hand_upper: tuple[float, float, float] = (0.033, 0.101, -0.036)


@dataclass(frozen=True)
class GraspCandidate:
    """A grasp: TCP pose, the opening it needs, contact quality in [0, 1], and the ranking score."""

    pose: Transform
    width: float
    quality: float
    score: float


@dataclass(frozen=True)
class GraspPreferences:
    """What the caller would like; each term adds to a candidate's score."""

    position: np.ndarray | None = None
    approach: np.ndarray | None = None
    plane_normal: np.ndarray | None = None


GRASP_DEPTHS = (0.025, 0.015, 0.0)  # how far past the contact pair, along the approach, the TCP may go
# The open fingers must clear an object by this much in all (a 7.6 cm apple in the Panda's 8 cm passes); the box
# grasps use the same margin.
WIDTH_MARGIN = 0.003
SURFACE_ALLOWANCE = 0.006  # metres beyond a contact where points still count as the object's own surface
SWEEP_CLEARANCE = 0.0025  # metres what the open fingers pass on the way in must clear them by
SWEEP_ABOVE = 0.003  # metres above the fingertips where that starts (below it: the contacts themselves)
UPWARD = 0.7  # normal's z above which a point faces up (within 45 degrees)
MIN_UPWARD_POINTS = 20  # fewer upward-facing points than this: the middle is taken over all points
# A grasp whose object, let go, would not fall free of the open fingers ranks behind those that do (see falls_free).
UNCLEAN_RELEASE_PENALTY = 1.5
PAD_FACE = 0.004  # metres either side of a closed pad's face where the object's surface counts as touching it
FRICTION_CONE = math.atan(0.5)  # a friction coefficient of 0.5, cautious for cardboard and plastic


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def antipodal_pairs(
    cloud: ObjectPoints,
    gripper: GripperGeometry,
    rng: np.random.Generator,
    seeds: int = 400,
    line_radius: float = 0.004,
) -> list[tuple[np.ndarray, np.ndarray, float, float]]:
    """``(center, closing_axis, quality, width)`` of antipodal point pairs that fit between the open fingers."""
    points, normals = cloud.points, cloud.normals
    if len(points) < 10:
        return []
    out = []
    cos_cone = math.cos(FRICTION_CONE)
    for i in rng.choice(len(points), size=min(seeds, len(points)), replace=False):
        p1, n1 = points[i], normals[i]
        axis = -n1
        rel = points - p1
        along = rel @ axis
        off_line = np.linalg.norm(rel - along[:, None] * axis, axis=1)
        candidates = (off_line < line_radius) & (along > 0.002) & (along < gripper.max_width - WIDTH_MARGIN)
        candidates &= normals @ axis > cos_cone
        if not candidates.any():
            continue
        j = np.flatnonzero(candidates)[np.argmax(along[candidates])]  # the outer surface on the far side
        p2, n2 = points[j], normals[j]
        closing = _unit(p2 - p1)
        angle = max(math.acos(np.clip(-n1 @ closing, -1, 1)), math.acos(np.clip(n2 @ closing, -1, 1)))
        if angle > FRICTION_CONE:
            continue
        out.append(((p1 + p2) / 2, closing, 1.0 - angle / FRICTION_CONE, float(np.linalg.norm(p2 - p1))))
    return out


def grasp_frames(center: np.ndarray, closing: np.ndarray, approaches: int = 12) -> list[np.ndarray]:
    """Rotations ``[x, y, z]`` with y along ``closing`` and z (the approach) turning about it; never from below."""
    helper = np.array([0.0, 0.0, 1.0]) if abs(closing[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = _unit(np.cross(closing, helper))
    v = np.cross(closing, u)
    frames = []
    for k in range(approaches):
        theta = 2 * math.pi * k / approaches
        z = math.cos(theta) * u + math.sin(theta) * v
        if z[2] > 0.2:  # the approach would come up from under the table
            continue
        frames.append(np.column_stack([np.cross(closing, z), closing, z]))
    return frames


def collides(
    rotation: np.ndarray, center: np.ndarray, scene: np.ndarray, gripper: GripperGeometry, width: float
) -> bool:
    """Whether the fingers, closing from fully open to ``width`` (plus a margin), or the hand behind them would
    contain any scene point."""
    return _collides_local(_in_gripper_slab((scene - center) @ rotation, gripper), gripper, width)


def _in_gripper_slab(local: np.ndarray, gripper: GripperGeometry) -> np.ndarray:
    """The points (in the TCP frame) no further along x than the fingers' or the hand's sides: only these can be
    in either. Most of a scene is outside that slab, and every test after it is on the few inside."""
    half = max(gripper.finger_breadth / 2, -gripper.hand_lower[0], gripper.hand_upper[0])
    return local[np.abs(local[:, 0]) < half]


def _gripper_reach(gripper: GripperGeometry) -> float:
    """How far from the TCP any point :func:`collides` tests for can be: the farthest corner of the hand's box and
    of the fingers' (as wide open as any grasp's margin makes them)."""
    fingers_y = gripper.max_width / 2 + SURFACE_ALLOWANCE + gripper.finger_thickness
    fingers_z = max(gripper.finger_length, gripper.tip_length)
    corners = [
        np.array([gripper.finger_breadth / 2, fingers_y, fingers_z]),
        np.maximum(np.abs(np.asarray(gripper.hand_lower)), np.abs(np.asarray(gripper.hand_upper))),
    ]
    return float(max(np.linalg.norm(c) for c in corners))


def _collides_local(local: np.ndarray, gripper: GripperGeometry, width: float) -> bool:
    """:func:`collides` with the scene's points already in the TCP frame."""
    x, y, z = local[:, 0], local[:, 1], local[:, 2]
    # Points just beyond the contacts are the object's own surface; but no further out than the open fingers'
    # inner faces, which pass that close to whatever stands beside a nearly full-width grasp (a cup's handle).
    inner = width / 2 + min(SURFACE_ALLOWANCE, max(gripper.max_width - width, 0.0) / 2 - 0.0005)
    outer = max(inner, gripper.max_width / 2) + gripper.finger_thickness
    in_finger_x = np.abs(x) < gripper.finger_breadth / 2
    fingers = in_finger_x & (np.abs(y) > inner) & (np.abs(y) < outer)
    fingers &= (z > -gripper.finger_length) & (z < gripper.tip_length)
    # What the open fingers pass on their way in (above the tips) must clear their inner faces by a margin: a
    # point cloud sees an edge a little inside where it is, and a cup's flared rim wider than the part held
    # (1 to 1.5 mm inside the 2F-85's open fingers, as seen) caught a finger; a 7.6 cm apple in the Panda's 8 cm
    # narrows above its middle and clears them by 3 mm or more.
    passed = _near_open_fingers(local, gripper, outer, -gripper.finger_length, -SWEEP_ABOVE)
    hand = np.all((local > np.asarray(gripper.hand_lower)) & (local < np.asarray(gripper.hand_upper)), axis=1)
    return bool(fingers.any() or passed.any() or hand.any())


def _near_open_fingers(
    local: np.ndarray, gripper: GripperGeometry, outer: float, z_low: float, z_high: float
) -> np.ndarray:
    """Which points (in the TCP frame) come within :data:`SWEEP_CLEARANCE` of the open fingers' inner faces, or
    into the fingers (out to ``outer``), between ``z_low`` and ``z_high`` along the approach."""
    x, y, z = local[:, 0], local[:, 1], local[:, 2]
    face = gripper.max_width / 2
    near = (np.abs(x) < gripper.finger_breadth / 2) & (z > z_low) & (z < z_high)
    return near & (np.abs(y) > face - SWEEP_CLEARANCE) & (np.abs(y) < outer)


def falls_free(
    rotation: np.ndarray, tcp: np.ndarray, points: np.ndarray, gripper: GripperGeometry, drop: float
) -> bool:
    """Whether the object, let go at this grasp and falling ``drop`` metres onto its support, passes the open
    fingers with the clearance it needs on the way in. A cup flaring 3 mm wider per centimetre, held across its
    body 2.5 mm inside the Panda's opening, fell 1.2 cm at the release and wedged its flare between the fingers,
    which carried it off as the hand left."""
    if drop <= 0.0:
        return True
    outer = gripper.max_width / 2 + gripper.finger_thickness
    for fall in (drop / 2, drop):
        local = (points - np.array([0.0, 0.0, fall]) - tcp) @ rotation
        if _near_open_fingers(local, gripper, outer, -gripper.finger_length, gripper.tip_length).any():
            return False
    return True


def pad_contact(rotation: np.ndarray, tcp: np.ndarray, points: np.ndarray, width: float, pad: float = 0.025) -> float:
    """How far, along the approach, the object's surface lies against the finger pads (metres). The pads, closing
    from ``width`` (the opening a grasp needs, or the full opening for a box grasp), stop at the object's widest
    points on each side; only points within :data:`PAD_FACE` of those count. A bottle held at its shoulder has
    its narrower neck between the pads too, but the pads touch only the body's top centimetre; counted whole, that
    grip looked as good as one lower down, and the bottle, held by its edge, sprang out of the opening hand."""
    local = (points - tcp) @ rotation
    between = (np.abs(local[:, 0]) < 0.01) & (np.abs(local[:, 1]) < width / 2 + PAD_FACE)
    between &= (local[:, 2] > -pad) & (local[:, 2] < 0.012)
    if not between.any():
        return 0.0
    across, along = local[between, 1], local[between, 2]
    touching = np.zeros(len(across), dtype=bool)
    for side in (across >= 0.0, across < 0.0):
        if side.any():
            face = np.abs(across[side]).max()
            touching[side] = np.abs(across[side]) > face - PAD_FACE
    z = along[touching]
    return float(z.max() - z.min())


@timed("grasp")
def detect_grasps(
    cloud: ObjectPoints,
    scene_points: np.ndarray,
    gripper: GripperGeometry,
    preferences: GraspPreferences | None = None,
    seed: int = 0,
    max_candidates: int = 40,
    release_drop: float = 0.0,
) -> list[GraspCandidate]:
    """Collision-free antipodal grasps on ``cloud``, best first.

    ``scene_points`` are every observed point (the object's own included): the fingers must clear all of them.
    ``release_drop``: how far a placed object falls when let go; grasps it would not fall free of rank lower.
    """
    preferences = preferences or GraspPreferences()
    rng = np.random.default_rng(seed)
    pairs = antipodal_pairs(cloud, gripper, rng) + rim_pairs(cloud, gripper.max_width - WIDTH_MARGIN)
    if not pairs:
        return []
    centre_of_object, radius = object_middle(cloud)
    near = scene_points[np.linalg.norm(scene_points - centre_of_object, axis=1) < 0.3]
    if len(near) > 6000:
        # Thinned, but never the object's own points: a rim the fingers pass must not be thinned away.
        near = np.vstack([cloud.points, near[rng.choice(len(near), size=6000, replace=False)]])
    out: list[GraspCandidate] = []
    reach = _gripper_reach(gripper) + max(GRASP_DEPTHS)  # nothing farther from a pair's middle can touch the hand
    for center, closing, quality, width in pairs:
        if width > gripper.max_width - WIDTH_MARGIN:
            continue
        around = near[np.einsum("ij,ij->i", near - center, near - center) < reach**2]
        for rotation in grasp_frames(center, closing):
            # As deep as the fingers go without touching anything: more of the pads on the object (a mug's rim
            # held by its top few millimetres slips out). The scene in the frame at the contacts' middle once; a
            # TCP deeper along the approach (z) only shifts it.
            local = _in_gripper_slab((around - center) @ rotation, gripper)
            for depth in GRASP_DEPTHS:
                tcp = center + depth * rotation[:, 2]
                if not _collides_local(local - np.array([0.0, 0.0, depth]), gripper, width):
                    break
            else:
                continue
            pose = Transform.from_rotation(tcp, rotation)
            score = _score(pose, width, quality, cloud, preferences, centre_of_object, radius)
            if not falls_free(rotation, tcp, cloud.points, gripper, release_drop):
                score -= UNCLEAN_RELEASE_PENALTY
            out.append(GraspCandidate(pose, width, quality, score))
    out.sort(key=lambda c: -c.score)
    return out[:max_candidates]


def score_grasp(
    pose: Transform, width: float, quality: float, cloud: ObjectPoints, preferences: GraspPreferences | None = None
) -> float:
    """The ranking score :func:`detect_grasps` gives a grasp, for grasps found otherwise (a box grasp at the
    middle of an object's footprint), so that all can be ranked together."""
    centre_of_object, radius = object_middle(cloud)
    return _score(pose, width, quality, cloud, preferences or GraspPreferences(), centre_of_object, radius)


def object_middle(cloud: ObjectPoints) -> tuple[np.ndarray, float]:
    """The object's middle and its horizontal radius about it. The middle is where most of it is as seen from
    above (the median of its upward-facing points), not the middle of its box: a mug's handle shifts its box's
    middle towards the handle, and grasps there would be preferred. Side faces are left out because only the
    cameras on their side see them: a box's one visible side pulled the median 1.6 cm off its middle, and the box,
    held there, turned about the fingers under its weight."""
    box_centre = (cloud.points.min(axis=0) + cloud.points.max(axis=0)) / 2
    seen_from_above = cloud.points[cloud.normals[:, 2] > UPWARD] if len(cloud.normals) else cloud.points
    if len(seen_from_above) < MIN_UPWARD_POINTS:
        seen_from_above = cloud.points
    centre = np.array([*np.median(seen_from_above[:, :2], axis=0), box_centre[2]])
    radius = max(float(np.max(np.linalg.norm(cloud.points[:, :2] - centre[:2], axis=1))), 0.03)
    return centre, radius


def _score(
    pose: Transform,
    width: float,
    quality: float,
    cloud: ObjectPoints,
    preferences: GraspPreferences,
    centre_of_object: np.ndarray,
    radius: float,
) -> float:
    # Grasps far from the middle (a mug's handle, a banana's end) let the object swing and slip; grasps with
    # little of the object between the finger pads (the top millimetres of a rim) slip out.
    tcp, rotation = pose.position, pose.rotation
    offset = float(np.linalg.norm(tcp[:2] - centre_of_object[:2])) / radius
    held = pad_contact(rotation, tcp, cloud.points, width)
    return quality - offset + 1.5 * min(held / 0.025, 1.0) + _preference_score(tcp, rotation, preferences)


def _preference_score(center: np.ndarray, rotation: np.ndarray, preferences: GraspPreferences) -> float:
    score = 0.0
    approach, closing = rotation[:, 2], rotation[:, 1]
    if preferences.position is not None:
        score += 2.0 * math.exp(-float(np.linalg.norm(center - preferences.position)) / 0.03)
    if preferences.approach is not None:
        score += 2.0 * float(approach @ _unit(np.asarray(preferences.approach, dtype=float)))
    else:  # top-down grasps are the easiest to reach and to place from
        score += 0.5 * float(-approach[2])
    if preferences.plane_normal is not None:
        score += 1.0 * abs(float(closing @ _unit(np.asarray(preferences.plane_normal, dtype=float))))
    return score
