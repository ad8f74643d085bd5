"""The errors a program may name in an ``except``: those the tools' doc-strings say they raise, and the two roots
(:class:`FailureError`: the robot could not; :class:`UsageError`: the call was wrong).

A program reads "GraspError where no grasp fits" and writes ``except GraspError:``; without the name, the ``except``
clause itself raised ``NameError`` just when the grasp failed.
"""

from __future__ import annotations

from roboscript.api.arguments import ArgumentError
from roboscript.api.compartments import CompartmentError
from roboscript.api.place_requests import PlacementError, ReceptacleFullError
from roboscript.errors import FailureError, UsageError
from roboscript.grasping.heuristics import GraspError
from roboscript.perception.base import UnknownObjectError
from roboscript.planning.errors import IKError, PlanningError, TrackingError

PROGRAM_ERRORS: dict[str, type[Exception]] = {
    cls.__name__: cls
    for cls in (
        FailureError,
        UsageError,
        GraspError,
        PlacementError,
        ReceptacleFullError,
        CompartmentError,
        PlanningError,
        IKError,
        TrackingError,
        ArgumentError,
        UnknownObjectError,
    )
}
