"""The retreats the tools make for a program: which of a program's own motions after a release count as its
retreat, and which leave the owed one to be made first."""

import math

import numpy as np

from roboscript.api.retreats import Owed
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend


def _tilted(degrees: float) -> np.ndarray:
    """Backing out of a grasp whose approach is tilted ``degrees`` off straight down: up and back."""
    a = math.radians(degrees)
    return np.array([0.0, -math.sin(a), math.cos(a)])


def test_rising_is_backing_out_only_within_20_degrees_of_a_tilted_release():
    # A UR5e let go of a cup gripped 39 degrees off vertical under its rim: the program's move straight up counted
    # as backing out (within the 60 degrees any retreat allows), and the fingers carried the cup up by its rim.
    with MujocoBackend("cluttered_2_pick_and_place", robot="ur5e", settle=0.3) as backend:
        retreats = build_tools(backend).retreats
        up = np.array([0.0, 0.0, 0.1])
        retreats.pending = Owed(_tilted(39.0), 0.03, "release", of_object=True)
        start = backend.tcp_pose().position
        assert retreats.first(up, shorter=True) is None  # the owed retreat was made first
        moved = backend.tcp_pose().position - start
        assert float(moved @ _tilted(39.0)) > 0.02
        for tilt in (0.0, 15.0):  # from above, or nearly along the way out: the program's move is its retreat
            retreats.pending = Owed(_tilted(tilt), 0.03, "release", of_object=True)
            assert retreats.first(up, shorter=True) is not None, tilt
        # A handle's bar leaves the fingers any way back: within the 60 degrees of any own retreat.
        retreats.pending = Owed(_tilted(39.0), 0.03, "release", of_object=False)
        assert retreats.first(up, shorter=True) is not None
