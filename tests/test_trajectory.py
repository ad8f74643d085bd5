"""Joint trajectories: sampled one time or many alike, and refused where malformed. (The product's time
parameterisation is tested with the planner, tests/test_planning.py.)"""

import numpy as np
import pytest

from helpers import min_jerk_through
from roboscript.trajectory import JointTrajectory, scaled_limits


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
        scaled_limits(np.ones(1), np.ones(1), speed_scale=2.0)
