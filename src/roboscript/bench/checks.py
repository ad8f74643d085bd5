"""The benchmark's checks, evaluated on ground-truth geometry at the end of a trial.

``in(a, b)``: at least 80% of a's box volume inside b's box (a door's: its compartment's), both in b's own axes.
``on(a, b)``: a's bottom above b's bottom and at least 80% of a's footprint over b's. ``at(a, p)``: a's centre within
0.1 m of p (or the check's own distance: ``at(a, p) within 0.05 m``). ``joint(j) > x``: a drawer or door opened
beyond x (metres or radians). ``near(a, b)``: a beside b, their footprints at most 8 cm apart and less than 20% of
either's over the other's (neither on nor in the other). Any of them negated (the original's ``flag_not``):
``not in(a, b)``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import Delaunay, QhullError

from roboscript.errors import InvalidArgumentError
from roboscript.sim.ground_truth import GroundTruth

FRACTION = 0.8
AT_TOLERANCE = 0.1
NEAR_GAP = 0.08
NEAR_OVERLAP = 0.2
OUTLINE_SAMPLES = 40  # grid points along each axis on which outlines' overlap is counted


@dataclass(frozen=True)
class CheckResult:
    name: str
    passed: bool
    detail: str

    def __post_init__(self) -> None:
        # Relations computed with numpy give numpy booleans, which records (JSON) cannot hold.
        object.__setattr__(self, "passed", bool(self.passed))

    def to_dict(self) -> dict:
        return {"check": self.name, "passed": self.passed, "detail": self.detail}


@dataclass(frozen=True)
class Check:
    """One check of a task; ``kind`` is in/on/near/at/joint; ``threshold``: how far a joint must be open, or how
    near ``at`` must be (:data:`AT_TOLERANCE` where 0); ``negate``: it passes when the relation does not hold."""

    kind: str
    subject: str
    target: str = ""
    point: tuple[float, float, float] | None = None
    threshold: float = 0.0
    negate: bool = False

    @property
    def name(self) -> str:
        if self.kind == "at":
            text = f"at({self.subject}, [{', '.join(f'{v:.3f}' for v in self.point)}])"
            if self.threshold:
                text += f" within {self.threshold:g} m"
        elif self.kind == "joint":
            text = f"joint({self.subject}) > {self.threshold:g}"
        else:
            text = f"{self.kind}({self.subject}, {self.target})"
        return f"not {text}" if self.negate else text

    def evaluate(self, gt: GroundTruth) -> CheckResult:
        result = self._relation(gt)
        if self.negate:
            return CheckResult(self.name, not result.passed, result.detail)
        return result

    def _relation(self, gt: GroundTruth) -> CheckResult:
        if self.kind == "in":
            inside = _share_inside(gt, self.subject, self.target)
            return CheckResult(self.name, inside >= FRACTION, f"{inside:.0%} of its volume inside")
        if self.kind == "on":
            a, b = gt.box(self.subject), gt.box(self.target)
            fraction = _footprint_over(a, b)
            above = bool(a.lower[2] >= b.lower[2] - 0.005)
            return CheckResult(
                self.name, above and fraction >= FRACTION, f"{fraction:.0%} of its footprint over, above: {above}"
            )
        if self.kind == "near":
            a, b = gt.box(self.subject), gt.box(self.target)
            gap = float(
                np.linalg.norm(np.clip(np.maximum(a.lower[:2] - b.upper[:2], b.lower[:2] - a.upper[:2]), 0, None))
            )
            over = _outlines_over(gt, self.subject, self.target, a, b)  # the smaller one's share: in or on either
            return CheckResult(
                self.name,
                gap <= NEAR_GAP and over < NEAR_OVERLAP,
                f"{gap:.3f} m apart, footprints {over:.0%} overlapping",
            )
        if self.kind == "at":
            distance = float(np.linalg.norm(gt.box(self.subject).center - np.asarray(self.point)))
            return CheckResult(self.name, distance <= (self.threshold or AT_TOLERANCE), f"{distance:.3f} m away")
        if self.kind == "joint":
            value = gt.joint(self.subject).value
            return CheckResult(self.name, value > self.threshold, f"at {value:.3f}")
        raise InvalidArgumentError(f"unknown check kind {self.kind!r}; kinds: in, on, near, at, joint")

    def to_dict(self) -> dict:
        return {
            "kind": self.kind,
            "subject": self.subject,
            "target": self.target,
            "point": self.point,
            "threshold": self.threshold,
            "negate": self.negate,
        }


def _outlines_over(gt: GroundTruth, first: str, second: str, a, b) -> float:
    """The larger of the shares of either's outline seen from above that lies within the other's: turned things
    side by side on the table have boxes that overlap from above (a tea box turned 150 degrees beside a golf ball:
    40%) though neither is in or on the other. The boxes' footprints where an outline has no area."""
    try:
        outlines = [gt.outline(first)[:, :2], gt.outline(second)[:, :2]]
        return max(_hull_share(outlines[0], outlines[1]), _hull_share(outlines[1], outlines[0]))
    except (ValueError, QhullError):  # no geometry, or an outline with no area (a flat sheet seen edge on)
        return max(_footprint_over(a, b), _footprint_over(b, a))


def _hull_share(inner: np.ndarray, outer: np.ndarray) -> float:
    """The share of the convex hull of points ``inner`` (N, 2) that lies within that of ``outer``, counted on a
    grid of :data:`OUTLINE_SAMPLES` squared points over ``inner``'s extent."""
    axes = [np.linspace(lo, hi, OUTLINE_SAMPLES) for lo, hi in zip(inner.min(axis=0), inner.max(axis=0), strict=True)]
    grid = np.column_stack([g.ravel() for g in np.meshgrid(*axes)])
    within_inner = Delaunay(inner).find_simplex(grid) >= 0
    within_both = within_inner & (Delaunay(outer).find_simplex(grid) >= 0)
    return float(within_both.sum() / max(within_inner.sum(), 1))


def _share_inside(gt: GroundTruth, subject: str, target: str) -> float:
    """The share of ``subject``'s box inside the space ``target`` holds things in (:meth:`GroundTruth.holding_space`),
    both boxes taken in ``target``'s own axes: a basket turned on the table has empty corners in its world box, and
    a thing standing there beside it is not in it."""
    frame, holding = gt.holding_space(target)
    box = gt.local_box(subject, frame)
    return box.intersection(holding).volume / max(box.volume, 1e-12)


def _footprint_over(a, b) -> float:
    """The fraction of box ``a``'s footprint that lies over box ``b``'s."""
    overlap = np.prod(np.clip(np.minimum(a.upper[:2], b.upper[:2]) - np.maximum(a.lower[:2], b.lower[:2]), 0, None))
    return float(overlap / max(np.prod(a.size[:2]), 1e-12))


def inside(a: str, b: str) -> Check:
    return Check("in", a, b)


def on(a: str, b: str) -> Check:
    return Check("on", a, b)


def at(a: str, point, within: float = 0.0) -> Check:
    return Check("at", a, point=tuple(float(v) for v in point), threshold=within)


def joint_above(part: str, threshold: float) -> Check:
    return Check("joint", part, threshold=threshold)
