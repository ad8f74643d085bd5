"""A small convex quadratic program with bounds on each variable, as each inverse-kinematics iteration poses.

Seven joint steps, a positive definite Hessian, each step bounded by the joint's distance to its limits. DAQP
(the solver mink uses) solves it in microseconds when called directly with simple bounds; building it as a general
problem through mink and qpsolvers cost a hundred times that, and IK ran thousands of iterations a trial. Where
no bound is active the linear solve alone answers.
"""

from __future__ import annotations

import daqp
import numpy as np

UNBOUNDED = 1e30  # what DAQP reads as no bound


def solve_box_qp(hessian: np.ndarray, linear: np.ndarray, lower: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """The ``x`` that minimises ``x.H.x / 2 + c.x`` subject to ``lower <= x <= upper`` (bounds may be infinite).

    ``hessian`` must be symmetric positive definite. Raises ValueError if the bounds cross or DAQP finds no
    solution.
    """
    n = len(linear)
    if hessian.shape != (n, n) or lower.shape != (n,) or upper.shape != (n,):
        raise ValueError(
            f"solve_box_qp: expected a {n}x{n} Hessian and {n} bounds each, got {hessian.shape}, "
            f"{lower.shape} and {upper.shape}"
        )
    # Most IK steps stay clear of the limits: the unconstrained minimiser is then feasible, hence the solution.
    # (Crossed bounds admit no point at all, so they are caught below, after this quick way out.)
    free = np.linalg.solve(hessian, -linear)
    if ((free >= lower) & (free <= upper)).all():
        return free
    if np.any(lower > upper):
        raise ValueError(f"solve_box_qp: a lower bound is above its upper bound: {lower} > {upper}")
    x, _, exitflag, _ = daqp.solve(
        np.ascontiguousarray(hessian, dtype=float),
        np.ascontiguousarray(linear, dtype=float),
        np.zeros((0, n)),
        np.clip(upper, -UNBOUNDED, UNBOUNDED).astype(float),
        np.clip(lower, -UNBOUNDED, UNBOUNDED).astype(float),
    )
    if exitflag < 1:
        raise ValueError(f"solve_box_qp: DAQP found no solution (exit flag {exitflag})")
    return np.asarray(x, dtype=float)
