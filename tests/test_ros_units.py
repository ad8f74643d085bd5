"""Pieces of the ROS side that need no master: finding a complete camera frame among lagging topics, the tool
calls a run's log records, and runs that end with a clear error when the master or the robot's state is missing."""

from __future__ import annotations

import socket
import threading
import time
from types import SimpleNamespace

import pytest

from helpers import ArmOnlyDriver
from roboscript.backends.driven import DriverBackend
from roboscript.drivers.base import DriverError, JointStateReading
from roboscript.geometry import Transform
from roboscript.robot_config import load_robot_config
from roboscript.ros.driver import _newest_complete
from roboscript.ros.master import check_master
from roboscript.run_log import logged_namespace


def _message(stamp: float) -> SimpleNamespace:
    return SimpleNamespace(header=SimpleNamespace(stamp=SimpleNamespace(to_sec=lambda: stamp)), stamp=stamp)


def test_a_frame_is_the_newest_instant_every_part_has_even_when_one_topic_lags():
    kept = {
        "rgb": [_message(t) for t in (1.0, 1.5, 2.0, 2.5)],
        "depth": [_message(t) for t in (0.5, 1.0, 1.5)],  # a frame and more behind
        "info": [_message(t) for t in (1.5, 2.0, 2.5)],
    }
    frame = _newest_complete(kept, not_before=0.0)
    assert {part: m.stamp for part, m in frame.items()} == {"rgb": 1.5, "depth": 1.5, "info": 1.5}
    assert _newest_complete(kept, not_before=1.6) is None  # none complete after the last motion ended
    assert _newest_complete({**kept, "depth": []}, not_before=0.0) is None


class RecordingLog:
    """Test double of RosRunLog: keeps the tool calls it is given."""

    def __init__(self):
        self.calls = []

    def tool_call(self, name, args, kwargs, answer=None, error=None):
        self.calls.append((name, args, kwargs, answer, error))


def test_each_tool_call_is_logged_with_its_answer_or_its_error():
    def grasp(pose, speed=1.0):
        """Grasps at pose."""
        if pose is None:
            raise ValueError("no pose")
        return "held"

    log = RecordingLog()
    namespace = logged_namespace({"grasp": grasp, "np": SimpleNamespace(), "Pose": SimpleNamespace}, log)
    assert namespace["grasp"]("p", speed=0.5) == "held"
    with pytest.raises(ValueError, match="no pose"):
        namespace["grasp"](None)
    assert log.calls == [
        ("grasp", ("p",), {"speed": 0.5}, "held", None),
        ("grasp", (None,), {}, None, "ValueError: no pose"),
    ]
    assert namespace["Pose"] is SimpleNamespace  # classes and modules are not tools
    assert namespace["grasp"].__doc__ == "Grasps at pose."


class LateSubscriberDriver(ArmOnlyDriver):
    """Test double of a driver whose joint-state subscriber falls behind: its reading is 5 s old until it has been
    asked ``late_for`` times, then fresh."""

    def __init__(self, names: list[str], late_for: int):
        self.names, self.late_for, self.asked = names, late_for, 0

    def joint_state(self) -> JointStateReading:
        self.asked += 1
        received = time.monotonic() - (5.0 if self.asked <= self.late_for else 0.0)
        return JointStateReading(dict.fromkeys(self.names, 0.0), 0.0, received)


def test_a_stale_joint_state_is_waited_on_while_the_arm_stands_still_but_not_during_a_motion():
    config = load_robot_config("panda_franka_ros")
    names = [*config.arm_driver_joints(), *config.gripper.width_joints]
    driver = LateSubscriberDriver(names, late_for=10**9)
    backend = DriverBackend(driver, config, Transform.identity())
    driver.late_for = driver.asked + 20  # late for 20 more polls (0.2 s), then the subscriber catches up
    assert backend.joint_positions().shape == (7,)
    driver.late_for = driver.asked + 20
    with pytest.raises(DriverError, match=r"joint states are stale: the last one on /joint_states arrived 5\.\d\d s"):
        backend._fresh_state(patience=0.0)  # as in a motion: no waiting
    assert driver.asked == driver.late_for - 19  # asked once, and refused at once
    driver.late_for = 10**9  # never again: lost
    asked = driver.asked
    with pytest.raises(DriverError, match="the robot's driver or the connection is down"):
        backend.joint_positions()
    assert driver.asked > asked + 1  # it kept asking through its patience before giving up


class StaleUntilDriver(ArmOnlyDriver):
    """Test double of a driver whose robot stopped publishing for a while: its reading is 5 s old until
    ``fresh_at`` (monotonic seconds), then fresh."""

    def __init__(self, names: list[str], fresh_at: float):
        self.names, self.fresh_at = names, fresh_at

    def joint_state(self) -> JointStateReading:
        now = time.monotonic()
        return JointStateReading(dict.fromkeys(self.names, 0.0), 0.0, now - (5.0 if now < self.fresh_at else 0.0))


def test_the_patience_for_a_stale_joint_state_grows_with_the_machines_load(monkeypatch):
    """Standing still, a joint state that stays stale for 1.5 times the patience of an idle machine (twice the state
    timeout) is waited out where the machine is three times busier than its cores, and lost where it is idle."""
    from roboscript.backends import driven

    config = load_robot_config("panda_franka_ros")
    names = [*config.arm_driver_joints(), *config.gripper.width_joints]
    late = 3 * config.state_timeout
    for factor, waited_out in ((3.0, True), (1.0, False)):
        monkeypatch.setattr(driven, "load_factor", lambda factor=factor: factor)
        driver = StaleUntilDriver(names, fresh_at=time.monotonic() + late)
        backend = DriverBackend(driver, config, Transform.identity())
        if waited_out:
            assert backend.joint_positions().shape == (7,)
        else:
            with pytest.raises(DriverError, match="the robot's driver or the connection is down"):
                backend.joint_positions()


def _in_thread(call) -> BaseException | None:
    """What ``call`` raised, run in a thread given 30 s (a call that never returns fails the test, not hangs it)."""
    raised: list[BaseException | None] = []

    def target():
        try:
            call()
            raised.append(None)
        except BaseException as error:  # handed to the test, whatever it is
            raised.append(error)

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(30.0)
    assert raised, "the call did not return: it would have hung the run"
    return raised[0]


def test_no_master_on_the_port_is_a_clear_error_not_an_endless_retry():
    with socket.socket() as probe:  # a port nothing listens on
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    error = _in_thread(lambda: check_master(f"http://127.0.0.1:{port}"))
    assert isinstance(error, DriverError)
    assert f"no ROS master answers at http://127.0.0.1:{port} (ConnectionRefusedError" in str(error)
    assert "--master URI" in str(error)


def test_a_master_that_accepts_but_never_answers_is_given_up_on():
    with socket.socket() as silent:
        silent.bind(("127.0.0.1", 0))
        silent.listen(1)  # the kernel accepts the connection; nothing ever answers it
        uri = f"http://127.0.0.1:{silent.getsockname()[1]}"
        error = _in_thread(lambda: check_master(uri, timeout=0.3))
    assert isinstance(error, DriverError)
    assert f"no ROS master answers at {uri} (TimeoutError" in str(error)


def test_no_master_uri_at_all_says_how_to_name_one(monkeypatch):
    monkeypatch.delenv("ROS_MASTER_URI", raising=False)
    with pytest.raises(DriverError, match="ROS_MASTER_URI is not set: start a master"):
        check_master()


class SilentDriver(LateSubscriberDriver):
    """Test double of a driver whose joint-state topic never publishes."""

    def joint_state(self) -> None:
        self.asked += 1
        return None


def test_a_joint_state_topic_that_never_publishes_ends_the_connection_with_its_name():
    config = load_robot_config("panda_franka_ros")
    driver = SilentDriver([], late_for=0)
    error = _in_thread(lambda: DriverBackend(driver, config, Transform.identity()))
    assert isinstance(error, DriverError)
    assert "no joint states on /joint_states within 2 s" in str(error)
    assert driver.asked > 1  # it waited for one before giving up


def _serve_once(reply: bytes) -> tuple[socket.socket, str]:
    """A loopback listener that answers its first connection with ``reply`` (test double of a service that is not a
    ROS master)."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(1)

    def answer():
        connection, _ = server.accept()
        with connection:
            connection.recv(65536)
            connection.sendall(reply)

    threading.Thread(target=answer, daemon=True).start()
    return server, f"http://127.0.0.1:{server.getsockname()[1]}"


def test_a_service_that_does_not_speak_http_is_no_master():
    server, uri = _serve_once(b"SSH-2.0-OpenSSH_9.2\r\n")
    with server:
        error = _in_thread(lambda: check_master(uri))
    assert isinstance(error, DriverError) and f"no ROS master answers at {uri}" in str(error)


def test_an_xml_rpc_server_that_is_not_a_master_is_named_as_such():
    body = (
        b"<?xml version='1.0'?><methodResponse><params><param><value><string>hello</string></value></param>"
        b"</params></methodResponse>"
    )
    reply = b"HTTP/1.1 200 OK\r\nContent-Type: text/xml\r\nContent-Length: %d\r\n\r\n%s" % (len(body), body)
    server, uri = _serve_once(reply)
    with server:
        error = _in_thread(lambda: check_master(uri))
    assert isinstance(error, DriverError) and "answered, but not as a ROS master does (getPid returned hello)" in str(
        error
    )
