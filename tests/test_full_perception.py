"""``--perception full`` reads nothing of the simulator's state: a task runs end to end through a backend that is
the Backend interface and nothing more (no ground truth, frames without segmentation, no segmentation labels),
with the packaged trained detector and the robot's pixels from its model; ground truth only judges the result."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from roboscript.assembly import build_perception, build_tools
from roboscript.backends.base import Backend
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.bench.tasks import get_task
from roboscript.perception.base import ObjectNotFoundError
from roboscript.perception.detection.trained_detector import TrainedDetector
from roboscript.perception.pipeline import PipelinePerception
from roboscript.sim.world_catalog import load_world


class SensorsOnly(Backend):
    """Test double: a simulation seen through the Backend interface only, as a real robot is. Its frames carry no
    segmentation and it has no ground truth; nothing else of the simulation can be reached through it."""

    def __init__(self, simulation: MujocoBackend):
        self._simulation = simulation
        self.captures = 0

    @property
    def robot(self):
        return self._simulation.robot

    def joint_positions(self):
        return self._simulation.joint_positions()

    def joint_states(self):
        return self._simulation.joint_states()

    def base_pose(self):
        return self._simulation.base_pose()

    def tcp_pose(self):
        return self._simulation.tcp_pose()

    def gripper_width(self):
        return self._simulation.gripper_width()

    def time(self):
        return self._simulation.time()

    def execute_trajectory(self, trajectory):
        return self._simulation.execute_trajectory(trajectory)

    def set_gripper(self, closed):
        return self._simulation.set_gripper(closed)

    def wait(self, seconds):
        self._simulation.wait(seconds)

    def camera_names(self):
        return self._simulation.camera_names()

    def capture(self, camera, color=True, segmentation=True):
        self.captures += 1
        return replace(self._simulation.capture(camera, color, segmentation=False), segmentation=None)


@pytest.fixture
def simple_0():
    task = get_task("simple_0")
    with MujocoBackend(task.world, robot="panda", seed=0, randomize=True) as simulation:
        yield task, simulation


def test_a_task_runs_end_to_end_on_sensors_alone(simple_0):
    task, simulation = simple_0
    robot = SensorsOnly(simulation)
    tools = build_tools(robot, "full", seed=0, scene=load_world(task.world))
    perception = tools.perception
    assert isinstance(perception, PipelinePerception) and isinstance(perception.grounder, TrainedDetector)
    assert perception.robot_index is None and perception.self_filter is not None
    namespace = tools.namespace()
    exec(task.reference_program(), namespace)
    assert robot.captures > 0
    checks = task.build_checks(simulation.ground_truth)
    results = [check.evaluate(simulation.ground_truth) for check in checks]
    assert all(r.passed for r in results), results


def test_what_it_sees_is_where_things_are(simple_0):
    task, simulation = simple_0
    tools = build_tools(SensorsOnly(simulation), "full", seed=0, scene=load_world(task.world))
    tools.detect_objects()
    truth = simulation.ground_truth
    for name in ("apple", "footed_bowl"):
        seen, actual = tools.perception.box(name), truth.box(name)
        assert np.linalg.norm(seen.center - actual.center) < 0.015, name
    with pytest.raises(ObjectNotFoundError, match=r"'unicorn' names nothing the detector knows"):
        tools.detect_objects(["unicorn"])
        tools.get_object_center_position("unicorn")


def test_in_simulation_full_perception_takes_the_same_path(simple_0, monkeypatch):
    _, simulation = simple_0
    perception = build_perception(simulation, "full")
    assert isinstance(perception.grounder, TrainedDetector) and perception.robot_index is None

    def no_truth(_):
        raise AssertionError("full perception read the simulator's ground truth")

    monkeypatch.setattr(MujocoBackend, "ground_truth", property(no_truth))
    perception.detect(None)
    assert "apple" in perception.objects()
