import numpy as np
import pytest

from roboscript.trajectory import JointTrajectory, min_jerk_through


def test_min_jerk_respects_limits_and_passes_through_waypoints():
    waypoints = np.array([[0.0, 0.0, 0.0], [1.0, -0.5, 0.2], [0.4, 0.3, -0.6]])
    vmax, amax = np.array([1.0, 0.5, 2.0]), np.array([3.0, 1.0, 4.0])
    traj = min_jerk_through(waypoints, vmax, amax)
    _, dq, ddq = traj.sample_many(np.linspace(0, traj.duration, 20000))
    assert np.all(np.abs(dq) <= vmax * 1.01)
    assert np.all(np.abs(ddq) <= amax * 1.05)
    np.testing.assert_allclose(traj.sample(0.0)[0], waypoints[0])
    np.testing.assert_allclose(traj.sample(traj.duration)[0], waypoints[-1])
    assert any(np.allclose(p, waypoints[1]) for p in traj.positions)
    np.testing.assert_allclose(traj.sample(traj.duration + 1.0)[1], 0.0)  # at rest after the end


def test_single_sample_agrees_with_batch():
    traj = min_jerk_through(np.array([[0.0, 1.0], [2.0, -1.0]]), np.ones(2), np.ones(2) * 2)
    for t in (0.1, 0.77, 1.5):
        one = traj.sample(t)
        many = traj.sample_many(np.array([t]))
        for a, b in zip(one, many, strict=True):
            np.testing.assert_allclose(a, b[0])


def test_malformed_trajectories_are_rejected():
    with pytest.raises(ValueError, match="increase strictly"):
        JointTrajectory(np.array([0.0, 0.0]), np.zeros((2, 2)), np.zeros((2, 2)))
    with pytest.raises(ValueError, match="shapes disagree"):
        JointTrajectory(np.array([0.0, 1.0]), np.zeros((3, 2)), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="non-finite"):
        JointTrajectory(np.array([0.0, 1.0]), np.array([[0.0], [np.nan]]), np.zeros((2, 1)))
    with pytest.raises(ValueError, match="speed_scale"):
        min_jerk_through(np.zeros((2, 1)), np.ones(1), np.ones(1), speed_scale=2.0)
