"""Which way a handle is approached: against its drawer's opening, or against its door's front beside it, never
by the plane its own few points fit (a bar on standoffs seen from above fits one that faces sideways)."""

from __future__ import annotations

import numpy as np

from roboscript.geometry import Box3D
from roboscript.grasping.heuristics import horizontal_grasps
from roboscript.perception.base import ArticulationJoint, ObjectPoints


class _DoorWithHandle:
    """Test double: a door facing +x with a vertical bar handle, whose own points fit a plane facing +y."""

    def __init__(self):
        self.handle = Box3D(np.array([-0.214, 0.72, 0.873]), np.array([-0.18, 0.736, 0.983]))
        self.hinge = ArticulationJoint(
            "cabinet.door_0", "revolute", np.array([-0.22, 0.415, 0.9]), np.array([0.0, 0.0, -1.0]), 0.0, 0.0, 1.7
        )

    def box(self, name):
        return self.handle

    def joints(self, name):
        return [self.hinge]

    def plane_normal(self, name, position):
        return np.array([1.0, 0.0, 0.0]) if name == "cabinet.door_0" else np.array([0.0, 1.0, 0.0])

    def points(self, name):
        return ObjectPoints(np.zeros((0, 3)), np.zeros((0, 3)))

    def footprint(self, name):
        return np.zeros(2), 0.0


def test_a_doors_handle_is_approached_against_the_doors_front():
    grasps = horizontal_grasps(_DoorWithHandle(), "cabinet.handle_2", None, 0.08, np.array([-0.45, 0.0]))
    first_approach = grasps[0].rotation[:, 2]
    assert np.allclose(first_approach, [-1.0, 0.0, 0.0], atol=1e-6)  # into the door, not along its face
    # The fingers close across the vertical bar, just inside its outermost surface.
    assert grasps[0].position[0] > -0.2 and abs(grasps[0].rotation[2, 1]) < 1e-6
