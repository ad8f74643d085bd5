"""The bounded QP of each IK iteration: against a general QP solver's formulation, and against brute force."""

import itertools

import numpy as np
import pytest
import qpsolvers

from roboscript.planning.box_qp import solve_box_qp


def _problem(rng: np.random.Generator, n: int):
    a = rng.normal(size=(6, n))
    hessian = a.T @ a + 1e-4 * np.eye(n)  # rank 6 plus damping, as in IK
    linear = rng.normal(size=n) * rng.uniform(0.1, 10)
    lower = -rng.uniform(0.0, 0.5, size=n)
    upper = rng.uniform(0.0, 0.5, size=n)
    lower[rng.random(n) < 0.2] = -np.inf  # some joints unlimited
    return hessian, linear, lower, upper


@pytest.mark.parametrize("n", [6, 7, 9])
def test_matches_a_general_qp_solver(n):
    rng = np.random.default_rng(n)
    active = 0
    for _ in range(300):
        hessian, linear, lower, upper = _problem(rng, n)
        x = solve_box_qp(hessian, linear, lower, upper)
        finite = np.isfinite(lower)
        g = np.vstack([np.eye(n), -np.eye(n)[finite]])
        h = np.concatenate([upper, -lower[finite]])
        reference = qpsolvers.solve_qp(hessian, linear, g, h, solver="daqp")
        assert np.all(x >= lower - 1e-9) and np.all(x <= upper + 1e-9)
        ours, theirs = (0.5 * v @ hessian @ v + linear @ v for v in (x, reference))
        assert ours <= theirs + 1e-9 * max(1.0, abs(theirs))
        np.testing.assert_allclose(x, reference, atol=1e-6)
        active += int(np.sum(np.isclose(x, lower) | np.isclose(x, upper)))
    assert active > 100  # the bounds were in play, not only interior optima


def _brute_force(hessian, linear, lower, upper):
    """Every choice of which bounds hold (each variable free, at its lower or at its upper bound): the feasible
    stationary point with the least objective."""
    n = len(linear)
    best, best_value = None, np.inf
    for choice in itertools.product((0, 1, 2), repeat=n):
        choice = np.array(choice)
        if np.any((choice == 1) & ~np.isfinite(lower)) or np.any((choice == 2) & ~np.isfinite(upper)):
            continue
        x = np.where(choice == 1, lower, np.where(choice == 2, upper, 0.0))
        free = choice == 0
        if free.any():
            x[free] = np.linalg.solve(hessian[free][:, free], -(linear[free] + hessian[free][:, ~free] @ x[~free]))
        if np.all(x >= lower - 1e-12) and np.all(x <= upper + 1e-12):
            value = 0.5 * x @ hessian @ x + linear @ x
            if value < best_value:
                best, best_value = x, value
    return best


def test_matches_every_active_set_tried_in_turn():
    rng = np.random.default_rng(7)
    for _ in range(100):
        hessian, linear, lower, upper = _problem(rng, 4)
        np.testing.assert_allclose(
            solve_box_qp(hessian, linear, lower, upper), _brute_force(hessian, linear, lower, upper), atol=1e-7
        )


def test_an_interior_optimum_is_the_unconstrained_one():
    hessian = np.diag([2.0, 4.0])
    x = solve_box_qp(hessian, np.array([-1.0, 2.0]), np.array([-1.0, -1.0]), np.array([1.0, 1.0]))
    np.testing.assert_allclose(x, [0.5, -0.5])


def test_crossed_bounds_are_refused():
    with pytest.raises(ValueError, match="lower bound is above its upper bound"):
        solve_box_qp(np.eye(2), np.zeros(2), np.array([0.1, -1.0]), np.array([0.0, 1.0]))


def test_an_optimum_clear_of_every_bound_is_the_unconstrained_one_and_a_bound_in_the_way_is_respected():
    rng = np.random.default_rng(3)
    hessian, linear, _, _ = _problem(rng, 7)
    free = np.linalg.solve(hessian, -linear)
    wide = np.abs(free) + 1.0
    np.testing.assert_allclose(solve_box_qp(hessian, linear, -wide, wide), free, rtol=1e-12)
    upper = wide.copy()
    upper[0] = free[0] - 0.5 if free[0] > -0.5 else -1.0  # joint 1's unconstrained step is cut off
    lower = np.minimum(-wide, upper - 1.0)
    x = solve_box_qp(hessian, linear, lower, upper)
    assert x[0] <= upper[0] + 1e-9 and not np.allclose(x, free)
