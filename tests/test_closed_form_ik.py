"""Closed-form IK of UR-shaped arms: every configuration of a pose, singular wrists, arms of another shape."""

import numpy as np
import pytest

from roboscript.geometry import Transform, quat_from_yaw, rotation_angle_between
from roboscript.planning.closed_form_ik import ClosedFormIK, NotClosedFormError
from roboscript.planning.errors import IKError
from roboscript.planning.ik import IKSearch, ik_solutions
from roboscript.planning.kinematics import ArmKinematics
from roboscript.robots import get_robot

MOUNT = Transform(np.array([-0.45, 0.0, 0.82]), quat_from_yaw(np.pi))


@pytest.fixture(scope="module")
def ur5e() -> ArmKinematics:
    return ArmKinematics(get_robot("ur5e"), MOUNT)


def turned_apart(a: np.ndarray, b: np.ndarray) -> float:
    """The largest joint difference, whole turns aside."""
    return float(np.max(np.abs((a - b + np.pi) % (2 * np.pi) - np.pi)))


def test_every_configuration_of_a_pose_is_found_and_reaches_it(ur5e):
    rng = np.random.default_rng(11)
    for k in range(300):
        q = rng.uniform(-np.pi, np.pi, 6)
        if k % 5 == 0:
            q[4] = 0.0  # the wrist singular: joints 2-4 and 6 turn about one axis
        target = ur5e.fk(q)
        solutions = ur5e.closed_form.solutions(target, q)
        assert 1 <= len(solutions) <= 8
        assert min(turned_apart(s, q) for s in solutions) < 1e-6
        for s in solutions:
            reached = ur5e.fk(s)
            assert np.linalg.norm(reached.position - target.position) < 1e-6
            assert rotation_angle_between(reached.quaternion, target.quaternion) < 1e-6


def test_a_pose_out_of_reach_has_no_solution_and_the_search_says_how_near_it_came(ur5e):
    far = Transform(np.array([1.5, 0.0, 1.0]), np.array([1.0, 0.0, 0.0, 0.0]))
    assert ur5e.closed_form.solutions(far, np.zeros(6)) == []
    with pytest.raises(IKError, match=r"\(no closed-form solution\); the nearest pose reached was"):
        ik_solutions(ur5e, far, np.array(get_robot("ur5e").home))


def test_ik_of_a_closed_form_arm_returns_the_branches_nearest_first_within_limits(ur5e):
    home = np.array(get_robot("ur5e").home)
    target = ur5e.fk(home + 0.2)
    solutions = ik_solutions(ur5e, target, home, search=IKSearch(solutions=8))
    assert len(solutions) >= 4
    distances = [float(np.sum((q - home) ** 2)) for q in solutions]
    assert distances == sorted(distances)
    np.testing.assert_allclose(solutions[0], home + 0.2, atol=1e-6)
    for q in solutions:
        assert np.all(q >= ur5e.lower) and np.all(q <= ur5e.upper)


def test_an_arm_of_another_shape_has_none_and_says_why(ur5e):
    panda = ArmKinematics(get_robot("panda"), MOUNT)
    assert panda.closed_form is None
    assert "seven" in panda.closed_form_absent or "7" in panda.closed_form_absent
    with pytest.raises(ValueError, match="no closed-form IK"):
        panda.closed_form_solutions(panda.fk(np.zeros(7)), np.zeros(7))
    axes = ur5e.closed_form.axes.copy()
    points = ur5e.closed_form.points.copy()
    tcp = ur5e.fk(np.zeros(6))
    tilted = axes.copy()
    tilted[2] = tilted[2] + np.array([0.0, 0.0, 0.05])
    with pytest.raises(NotClosedFormError, match="joint 3's axis is not parallel"):
        ClosedFormIK.from_zero_configuration(tilted, points, tcp)
    apart = points.copy()
    apart[5] = apart[5] + 0.01 * np.cross(axes[4], axes[5])
    with pytest.raises(NotClosedFormError, match=r"joints 5 and 6 miss each other by 10\.00 mm"):
        ClosedFormIK.from_zero_configuration(axes, apart, tcp)
