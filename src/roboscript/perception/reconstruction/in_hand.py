"""Where a held object sits in the hand, from a look at it there: the points the store has of it, laid onto what
the cameras see of it now by a trimmed point-to-point ICP.

A thing taken by its rim or its side can turn between the fingers as it is lifted (a mug held at its rim tips
10 degrees and hangs 2 cm lower at one side); carried on as it was seen before the grasp, it is set down into its
support or swept into what stands beside the path. What the cameras see of it in the hand is only part of it (the
fingers and the hand hide the rest), so the whole surface seen before is moved to fit that part rather than
replaced by it.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import cKDTree

from roboscript.geometry import Transform, rotation_angle_between
from roboscript.perception.points import evenly_spread

SAMPLE = 1500  # points of each cloud that take part
ROUNDS = 40  # ICP iterations at most
KEPT = 0.8  # share of the closest pairs each iteration fits (the rest: fingers' edges, neighbours' bits)
CONVERGED = 1e-5  # metres of motion of the observed points below which the fit has settled
LEAST_SEEN = 50  # points seen in the hand below which nothing is told
FIT = 0.004  # metres: the median distance of the kept pairs at most for the fit to be believed
BETTER = 0.001  # metres by which the fit must bring the seen points nearer than where the object was expected
RISE = 0.003  # metres its lowest points may rise in the hand at most: what hangs from fingers turns or slides down
LOWEST = 2.0  # percentile of the heights that stands for its lowest points
MOST_TURN = math.radians(45)  # a fit that turns the object more than this in the hand is a wrong one
MOST_SHIFT = 0.06  # metres: ... or moves it more than this


def register(model: np.ndarray, seen: np.ndarray) -> Transform | None:
    """The rigid motion (world frame) that takes ``model`` (the object's surface where it was expected, (N, 3)) to
    where ``seen`` (the part of it the cameras see now, (M, 3)) shows it; None where too little was seen, where the
    object is where it was expected (the fit does not bring the seen points :data:`BETTER` nearer), where the fit
    is poor, or where it would move the object implausibly: far, or its bottom up (bits of the fingers among the
    seen points pull a fit towards the hand; a thing tipping about the fingers may raise its top, not its bottom)."""
    if len(seen) < LEAST_SEEN or len(model) < LEAST_SEEN:
        return None
    model, seen = evenly_spread(model, SAMPLE), evenly_spread(seen, SAMPLE)
    tree = cKDTree(model)
    expected_fit = _fit(tree, seen)
    # Seen points are fitted onto the model (each has a counterpart there; the model has parts not seen): the
    # transform found takes the seen to the model, so its inverse takes the model to where it is seen.
    to_model = Transform.identity()
    moving = seen
    for _ in range(ROUNDS):
        distances, index = tree.query(moving)
        kept = distances <= np.quantile(distances, KEPT)
        step = _best_fit(moving[kept], model[index[kept]])
        moved = step.apply(moving)
        to_model = step.compose(to_model)
        settled = float(np.max(np.linalg.norm(moved - moving, axis=1))) < CONVERGED
        moving = moved
        if settled:
            break
    fit = _fit(tree, moving)
    if fit > FIT or fit > expected_fit - BETTER:
        return None
    motion = to_model.inverse()
    center = model.mean(axis=0)
    shift = float(np.linalg.norm(motion.apply(center) - center))
    rise = float(np.percentile(motion.apply(model)[:, 2], LOWEST) - np.percentile(model[:, 2], LOWEST))
    turn = rotation_angle_between(motion.quaternion, Transform.identity().quaternion)
    if turn > MOST_TURN or shift > MOST_SHIFT or rise > RISE:
        return None
    return motion


def _fit(tree: cKDTree, points: np.ndarray) -> float:
    """The median distance of the kept share (:data:`KEPT`) of ``points`` nearest the model in ``tree``."""
    distances = np.sort(tree.query(points)[0])
    return float(np.median(distances[: max(1, int(len(distances) * KEPT))]))


def _best_fit(source: np.ndarray, target: np.ndarray) -> Transform:
    """The rigid motion that takes ``source`` nearest ``target`` pair by pair (least squares, Kabsch)."""
    source_center, target_center = source.mean(axis=0), target.mean(axis=0)
    covariance = (source - source_center).T @ (target - target_center)
    u, _, vt = np.linalg.svd(covariance)
    sign = np.sign(np.linalg.det(vt.T @ u.T)) or 1.0
    rotation = vt.T @ np.diag([1.0, 1.0, sign]) @ u.T
    return Transform.from_rotation(target_center - rotation @ source_center, rotation)

