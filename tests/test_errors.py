"""One root for every error RoboScript raises on purpose, a failure branch and a usage branch, builtins kept."""

import ast
from pathlib import Path

import pytest

from roboscript.api.place_requests import PlacementError, ReceptacleFullError
from roboscript.api.signature import ToolCallError
from roboscript.bench.task_file import TaskFileError
from roboscript.codegen.outcomes import Outcome
from roboscript.codegen.sandbox import classify_exception
from roboscript.errors import FailureError, RoboScriptError, UsageError, error_message
from roboscript.grasping.heuristics import GraspError
from roboscript.perception.base import UnknownObjectError
from roboscript.planning.errors import IKError, PlannerTimeoutError, TrackingError, UnknownPlannerError
from roboscript.sim.world_file import WorldFileError

SOURCE = Path(__file__).resolve().parents[1] / "src" / "roboscript"


def test_every_error_class_in_the_source_has_the_common_root():
    """Read from the source, so that modules with optional dependencies (ROS, Ray) are covered too."""
    bases: dict[str, list[str]] = {}
    for path in SOURCE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ClassDef) and node.name.endswith(("Error", "Exception")):
                bases[node.name] = [b.id if isinstance(b, ast.Name) else b.attr for b in node.bases]

    def rooted(name: str) -> bool:
        return name == "RoboScriptError" or any(rooted(b) for b in bases.get(name, []))

    unrooted = sorted(n for n in bases if not rooted(n))
    assert not unrooted, f"error classes outside RoboScriptError: {unrooted}"
    assert len(bases) >= 20


@pytest.mark.parametrize(
    "error", [PlacementError, ReceptacleFullError, GraspError, IKError, TrackingError, PlannerTimeoutError]
)
def test_what_the_robot_could_not_do_is_a_failure(error):
    assert issubclass(error, FailureError) and not issubclass(error, UsageError)


@pytest.mark.parametrize(
    "error", [UnknownObjectError, ToolCallError, WorldFileError, TaskFileError, UnknownPlannerError]
)
def test_what_was_asked_wrongly_is_usage(error):
    assert issubclass(error, UsageError) and not issubclass(error, FailureError)


def test_builtin_bases_are_kept_and_the_classifier_catches_by_branch():
    assert issubclass(GraspError, ValueError) and issubclass(UnknownObjectError, KeyError)
    assert issubclass(TrackingError, RuntimeError) and issubclass(ToolCallError, TypeError)
    assert issubclass(FailureError, RoboScriptError) and issubclass(UsageError, RoboScriptError)
    assert classify_exception(TrackingError(0.1, 0.02)) is Outcome.PLANNING_FAILURE
    assert classify_exception(GraspError("no grasp")) is Outcome.PLANNING_FAILURE
    assert classify_exception(UnknownObjectError("x", ["apple"])) is Outcome.RUNTIME_ERROR
    assert classify_exception(ZeroDivisionError()) is Outcome.RUNTIME_ERROR
    assert error_message(UnknownObjectError("x", ["apple"])).startswith("no object named 'x'")


def test_a_bad_value_given_to_a_run_is_a_usage_error_and_still_a_value_error():
    from roboscript.bench.benchmark import trial_specs
    from roboscript.errors import InvalidArgumentError, UsageError

    with pytest.raises(InvalidArgumentError, match="trials must be at least 1, got 0") as caught:
        trial_specs("simple_0", "open_gripper()", "panda", 0, 0, 60.0)
    assert isinstance(caught.value, UsageError) and isinstance(caught.value, ValueError)
