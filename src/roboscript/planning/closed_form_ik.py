"""Closed-form inverse kinematics for six-joint arms shaped like Universal Robots' arms: every solution of a TCP
pose at once, in microseconds, where the iterative solver needs a random seed per branch and a millisecond per seed.

The shape, read off the arm's own model at its zero configuration (nothing here knows a UR5e's dimensions): joints
2, 3 and 4 turn about parallel axes, perpendicular to joint 1's; joint 5's axis is perpendicular to them; joints 5
and 6 have intersecting axes, perpendicular to each other. The arm is written as a product of exponentials
``T(q) = E1(q1) ... E6(q6) M`` (``Ei`` the screw motion about joint i's axis at zero, ``M`` the TCP at zero), and
the pose is taken apart one joint at a time:

1. The wrist centre (where axes 5 and 6 meet) moves only with joints 1-4, and joints 2-4 keep its offset along
   their common axis: that offset fixes joint 1 (two solutions, shoulder left or right).
2. Joints 2-4 keep the component of axis 6 along their common axis too, and joint 5 alone sets it: joint 5 (two
   solutions, wrist up or down).
3. The rest of the orientation gives the sum of joints 2-4 and joint 6.
4. The wrist centre less the fixed last link gives joint 4's axis point, which joints 2 and 3 reach as a planar
   two-link arm: joint 3 by the law of cosines (two solutions, elbow up or down), then joints 2 and 4.

So up to eight solutions, each checked by forward kinematics before it is returned.
"""

from __future__ import annotations

import math

import numpy as np

from roboscript.errors import UsageError
from roboscript.geometry import Transform

# Where the wrist is singular (axis 6 along joints 2-4's axis), joints 2-4 and 6 turn about the same axis and only
# their sum is fixed; joint 6 keeps the reference's value then.
SINGULAR = 1e-9
PARALLEL = 1e-6  # how far (sine of the angle, or metres) the model may be from the shape above


class NotClosedFormError(UsageError, ValueError):
    """The arm does not have the shape this solver needs; says which part differs."""


def _skew(axis: np.ndarray) -> np.ndarray:
    """The matrix K with K @ v = axis x v (np.cross costs twenty times a matrix product on 3-vectors)."""
    x, y, z = axis
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


class _Turn:
    """Rotations about one fixed unit axis (Rodrigues), with that axis's cross products precomputed."""

    def __init__(self, axis: np.ndarray):
        self.axis = axis
        self.skew = _skew(axis)
        self.skew2 = self.skew @ self.skew

    def matrix(self, angle: float) -> np.ndarray:
        return np.eye(3) + math.sin(angle) * self.skew + (1.0 - math.cos(angle)) * self.skew2

    def angle(self, source: np.ndarray, target: np.ndarray) -> float:
        """The turn about the axis that takes ``source``'s direction across the plane normal to it to
        ``target``'s: atan2 of axis . (source x target) = -source . (axis x target), and source . target."""
        return math.atan2(-float(source @ (self.skew @ target)), float(source @ target))


def _cos_sin_roots(a: float, b: float, c: float) -> list[float]:
    """The angles t in (-pi, pi] with a cos t + b sin t = c (none, or two that may coincide)."""
    r = math.hypot(a, b)
    if r < SINGULAR:
        return []
    ratio = c / r
    if abs(ratio) > 1.0 + 1e-9:
        return []
    offset = math.acos(min(1.0, max(-1.0, ratio)))
    base = math.atan2(b, a)
    return [_wrapped(base + offset), _wrapped(base - offset)]


def _wrapped(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi


def _flat(vector: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """``vector`` less its component along the unit ``normal``."""
    return vector - (vector @ normal) * normal


class ClosedFormIK:
    """Every TCP solution of a UR-shaped arm; build it with :meth:`from_zero_configuration`."""

    def __init__(self, axes: np.ndarray, points: np.ndarray, normal: np.ndarray, wrist: np.ndarray, tcp: Transform):
        """Use :meth:`from_zero_configuration`, which checks the arm's shape first."""
        self.axes, self.points, self.normal = axes, points, normal
        self.signs = np.sign(axes[1:4] @ normal)  # axes 2-4 along or against their common direction
        self.wrist = wrist  # where axes 5 and 6 meet, at the zero configuration
        self.wrist_in_tcp = tcp.inverse().apply(wrist[None])[0]  # fixed: the point lies on axis 6
        self.tcp_rotation = tcp.rotation
        self._base, self._common, self._wrist_5, self._wrist_6 = (_Turn(axes[j]) for j in (0, 1, 4, 5))
        # What the steps below use of the zero configuration: none of it depends on the target.
        self._offset = float(normal @ (wrist - points[0]))  # the wrist centre's offset along axes 2-4
        self._axis_6 = (float(normal @ axes[5]), float(normal @ (self._wrist_5.skew @ axes[5])))
        self._last_link = wrist - points[3]
        self._upper = _flat(points[2] - points[1], normal)
        self._fore = _flat(points[3] - points[2], normal)
        self._elbow = (float(self._upper @ self._fore), float(self._upper @ (self._common.skew @ self._fore)))
        self._lengths = float(self._upper @ self._upper + self._fore @ self._fore)
        self._across_6 = _perpendicular(axes[5])
        self._across_common = _perpendicular(normal)

    @staticmethod
    def from_zero_configuration(axes: np.ndarray, points: np.ndarray, tcp: Transform) -> ClosedFormIK:
        """The solver for an arm whose joint axes (unit vectors) pass through ``points`` and whose TCP is at
        ``tcp`` when every joint is at zero. Raises :class:`NotClosedFormError` naming the joints that do not
        have the shape this solver needs."""
        axes = np.asarray(axes, dtype=float)
        points = np.asarray(points, dtype=float)
        if axes.shape != (6, 3) or points.shape != (6, 3):
            raise NotClosedFormError(f"a closed form needs six joints, this arm has {len(axes)}")
        axes = axes / np.linalg.norm(axes, axis=1, keepdims=True)
        normal = axes[1]
        for j in (2, 3):
            if np.linalg.norm(_skew(normal) @ axes[j]) > PARALLEL:
                raise NotClosedFormError(f"joint {j + 1}'s axis is not parallel to joint 2's")
        for j in (0, 4):
            if abs(axes[j] @ normal) > PARALLEL:
                raise NotClosedFormError(f"joint {j + 1}'s axis is not perpendicular to joints 2-4's")
        if abs(axes[4] @ axes[5]) > PARALLEL:
            raise NotClosedFormError("joints 5 and 6 do not have perpendicular axes")
        wrist, gap = _meeting_point(points[4], axes[4], points[5], axes[5])
        if gap > PARALLEL:
            raise NotClosedFormError(f"the axes of joints 5 and 6 miss each other by {gap * 1000:.2f} mm")
        return ClosedFormIK(axes, points, normal, wrist, tcp)

    def solutions(self, target: Transform, reference: np.ndarray) -> list[np.ndarray]:
        """The joint configurations that put the TCP at ``target``, each angle in [-pi, pi) (turn them by whole
        turns to fit the limits); ``reference`` gives joint 6 where the wrist is singular."""
        n, base = self.normal, self._base
        target_rotation = target.rotation
        rotation = target_rotation @ self.tcp_rotation.T  # the joints' rotation: R1 Rn(phi) R5 R6
        wrist = target_rotation @ self.wrist_in_tcp + target.position
        arm = wrist - self.points[0]
        out = []
        for q1 in _cos_sin_roots(float(n @ arm), -float(n @ (base.skew @ arm)), self._offset):
            r1 = base.matrix(q1)
            after_1 = r1.T @ rotation  # Rn(phi) R5 R6
            axis_6 = after_1 @ self.axes[5]
            for q5 in _cos_sin_roots(*self._axis_6, float(n @ axis_6)):
                r5 = self._wrist_5.matrix(q5)
                phi, q6 = self._phi_and_q6(after_1, r5, axis_6, float(reference[5]))
                for q2, q3, q4 in self._shoulder_elbow(r1, phi, wrist):
                    out.append(np.array([q1, q2, q3, q4, q5, q6]))
        return out

    def _phi_and_q6(
        self, after_1: np.ndarray, r5: np.ndarray, axis_6: np.ndarray, q6_reference: float
    ) -> tuple[float, float]:
        """The turn of joints 2-4 together about their common axis, and joint 6."""
        n, common = self.normal, self._common
        from_5 = _flat(r5 @ self.axes[5], n)
        seen = _flat(axis_6, n)
        if from_5 @ from_5 > SINGULAR and seen @ seen > SINGULAR:
            phi = common.angle(from_5, seen)
            # R6 = R5^T Rn(phi)^T (Rn(phi) R5 R6): measured on a direction across axis 6.
            across = self._across_6
            turned = r5.T @ common.matrix(phi).T @ after_1 @ across
            return phi, self._wrist_6.angle(across, turned)
        q6 = q6_reference
        across = self._across_common
        return common.angle(across, after_1 @ self._wrist_6.matrix(q6).T @ r5.T @ across), q6

    def _shoulder_elbow(self, r1: np.ndarray, phi: float, wrist: np.ndarray) -> list[tuple[float, float, float]]:
        """Joints 2-4 that carry joint 4's axis point where the wrist centre needs it, with joints 2-4 summing to
        ``phi`` (about their common axis)."""
        n, points, common = self.normal, self.points, self._common
        joint_4 = wrist - r1 @ (common.matrix(phi) @ self._last_link)
        reach = _flat(points[0] + r1.T @ (joint_4 - points[0]) - points[1], n)  # in the zero configuration's frame
        out = []
        for q3 in _cos_sin_roots(*self._elbow, (float(reach @ reach) - self._lengths) / 2):
            elbow = self._upper + common.matrix(q3) @ self._fore
            q2 = common.angle(elbow, reach)
            signed = self.signs * (q2, q3, phi - q2 - q3)
            out.append((_wrapped(signed[0]), _wrapped(signed[1]), _wrapped(signed[2])))
        return out


def _perpendicular(axis: np.ndarray) -> np.ndarray:
    """A unit vector perpendicular to the unit ``axis``."""
    other = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    out = _skew(axis) @ other
    return out / np.linalg.norm(out)


def _meeting_point(p: np.ndarray, u: np.ndarray, r: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, float]:
    """The midpoint of the closest points of two lines (point, unit direction), and their distance."""
    w = p - r
    b = u @ v
    denominator = 1.0 - b * b
    if denominator < PARALLEL:
        return p, float(np.linalg.norm(_flat(w, u)))
    s = (b * (v @ w) - (u @ w)) / denominator
    t = ((v @ w) - b * (u @ w)) / denominator
    on_first, on_second = p + s * u, r + t * v
    return (on_first + on_second) / 2, float(np.linalg.norm(on_first - on_second))
