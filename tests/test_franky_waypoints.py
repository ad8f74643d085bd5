"""How a plan becomes franky's waypoints (no franky needed): even steps interpolated from the plan, their minimum
times adding up to the plan's duration, the last at the plan's end and at rest."""

from __future__ import annotations

import numpy as np

from helpers import min_jerk_through
from roboscript.drivers.franky import waypoint_samples
from roboscript.robots import get_robot
from roboscript.trajectory import JointTrajectory


def _plan() -> JointTrajectory:
    robot = get_robot("fr3")
    home = np.array(robot.home)
    path = home + np.array([np.zeros(7), [0.3, -0.2, 0.1, 0.2, 0.0, 0.1, -0.3], [0.5, 0, 0, 0, 0, 0, 0]])
    dense = min_jerk_through(path, np.array(robot.max_velocity), np.array(robot.max_acceleration), 0.1)
    # uneven samples, as a time-parameterised plan has them: denser where it is fast, a long last one
    last = len(dense.times) - 1
    keep = np.unique(np.r_[np.round(np.linspace(0, 1, 40) ** 0.7 * (last - 30)).astype(int), last])
    return JointTrajectory(dense.times[keep], dense.positions[keep], dense.velocities[keep])


def test_waypoints_are_even_steps_of_the_plan_that_add_up_to_its_duration():
    plan = _plan()
    assert len(set(np.round(np.diff(plan.times), 4))) > 3  # the plan's own samples are uneven
    steps, positions, velocities = waypoint_samples(plan, 0.05)
    assert sum(steps) == round(1000 * plan.duration)
    assert max(steps) <= 50 and min(steps[:-1]) >= 45  # even, within a millisecond's rounding
    times = np.cumsum(steps) / 1000
    q, dq, _ = plan.sample_many(times)
    # on the plan's path and pace, give or take the half millisecond each step is rounded to
    assert np.allclose(positions, q, atol=1e-3) and np.allclose(velocities[:-1], dq[:-1], atol=1e-2)
    assert np.allclose(positions[-1], plan.positions[-1]) and not velocities[-1].any()


def test_a_plan_shorter_than_a_step_is_one_waypoint_at_its_end():
    plan = JointTrajectory(np.array([0.0, 0.02]), np.array([np.zeros(7), np.full(7, 0.001)]), np.zeros((2, 7)))
    steps, positions, velocities = waypoint_samples(plan, 0.05)
    assert steps == [20] and np.allclose(positions, [np.full(7, 0.001)]) and not velocities.any()
