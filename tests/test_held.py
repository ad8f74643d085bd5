"""What the gripper holds: one list, and one event to the parts that follow it."""

import numpy as np
import pytest

from roboscript.api.held import Held
from roboscript.assembly import build_tools
from roboscript.backends.mujoco_backend import MujocoBackend
from roboscript.geometry import Transform

HAND = Transform(np.array([0.1, 0.2, 0.9]), np.array([0.0, 1.0, 0.0, 0.0]))


class RecordingFollower:
    """Test double: writes down what it hears."""

    def __init__(self, label: str, heard: list):
        self.label, self.heard = label, heard

    def taken(self, name, is_object, gripper):
        self.heard.append((self.label, "taken", name, is_object))

    def let_go(self, name, is_object, gripper):
        self.heard.append((self.label, "let_go", name, is_object))


def test_followers_hear_taking_in_order_and_letting_go_in_reverse():
    heard: list = []
    held = Held([RecordingFollower("planning", heard), RecordingFollower("perception", heard)])
    held.take("apple", True, HAND)
    held.take("apple", True, HAND)  # held already: nothing new to tell
    held.take("cabinet.drawer_1", False, HAND)
    assert held.names == ["apple", "cabinet.drawer_1"] and "apple" in held and len(held) == 2
    held.let_go("apple", HAND)
    assert heard == [
        ("planning", "taken", "apple", True),
        ("perception", "taken", "apple", True),
        ("planning", "taken", "cabinet.drawer_1", False),
        ("perception", "taken", "cabinet.drawer_1", False),
        ("perception", "let_go", "apple", True),
        ("planning", "let_go", "apple", True),
    ]
    with pytest.raises(ValueError, match=r"'apple' is not attached; attached: cabinet\.drawer_1"):
        held.let_go("apple", HAND)


def test_the_tools_planning_scene_follows_what_is_held():

    with MujocoBackend("cluttered_2_pick_and_place", robot="panda", settle=0.5) as backend:
        tools = build_tools(backend)
        tools.attach_object("plum")
        assert tools.held.names == ["plum"] and tools.motion.scene.attached == ["plum"]
        tools.detach_object("plum")
        assert not tools.held and tools.motion.scene.attached == []
