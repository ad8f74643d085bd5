"""Motion planning: planning scene, IK, OMPL planners, Cartesian and arc paths, time parameterisation, execution."""

from roboscript.planning.cartesian import CartesianResult, arc_poses, cartesian_path
from roboscript.planning.errors import (
    CartesianPathIncompleteError,
    IKError,
    PathInCollisionError,
    PlannerTimeoutError,
    PlanningError,
    StateInCollisionError,
    TrackingError,
    UnknownPlannerError,
)
from roboscript.planning.ik import IKSearch, ik_solutions
from roboscript.planning.kinematics import ArmKinematics
from roboscript.planning.motion import MotionPlanner
from roboscript.planning.planner import JointPath, JointPlanner, planner_names
from roboscript.planning.scene import PlanningScene
from roboscript.planning.timing import time_parameterize

__all__ = [
    "ArmKinematics",
    "CartesianPathIncompleteError",
    "CartesianResult",
    "IKError",
    "IKSearch",
    "JointPath",
    "JointPlanner",
    "MotionPlanner",
    "PathInCollisionError",
    "PlannerTimeoutError",
    "PlanningError",
    "PlanningScene",
    "StateInCollisionError",
    "TrackingError",
    "UnknownPlannerError",
    "arc_poses",
    "cartesian_path",
    "ik_solutions",
    "planner_names",
    "time_parameterize",
]
