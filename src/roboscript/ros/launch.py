"""Starting the ROS side of a run as processes: a rosmaster on a free loopback port and `roboscript ros-sim`, each
stopped when the run ends; and asking the twin to evaluate a task's checks on its own state."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
import uuid
from dataclasses import dataclass, field

from roboscript.drivers.base import DriverError
from roboscript.processes import die_with_parent

EVALUATE_TOPIC = "/roboscript/evaluate"
EVALUATION_TOPIC = "/roboscript/evaluation"
START_TIMEOUT = 120.0  # seconds for ros-sim to build its world and start serving (a busy machine included)


def _die_with_parent() -> None:
    """Masters and twins get SIGTERM when the process that started them exits, however that exits (trial processes
    end with os._exit, which runs no clean-up), so none outlives its run."""
    die_with_parent(signal.SIGTERM)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


MASTER_ATTEMPTS = 5  # ports tried before giving up: another run may take a free port before our master binds it


def start_master(ros_home: str | None = None) -> tuple[subprocess.Popen, str]:
    """A rosmaster on a free loopback port, and its URI, once it answers; it is stopped when this process exits.

    The master that answers must be the one started here (its pid is asked): a port found free can be taken by a
    run beside this one before our master binds it, and two runs on one master would drive each other's robots."""
    failures = []
    for _ in range(MASTER_ATTEMPTS):
        process, uri, why = _try_master(free_port(), ros_home)
        if process is not None:
            return process, uri
        failures.append(why)
    raise DriverError(f"no rosmaster of ours started in {MASTER_ATTEMPTS} attempts: " + "; ".join(failures))


def _try_master(port: int, ros_home: str | None) -> tuple[subprocess.Popen | None, str, str]:
    """(process, uri, "") when a master of ours answers on ``port``, else (None, uri, why not)."""
    import rosgraph

    uri = f"http://127.0.0.1:{port}"
    env = {**os.environ, **({"ROS_HOME": ros_home} if ros_home else {})}
    process = subprocess.Popen(
        ["rosmaster", "--core", "-p", str(port)],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        preexec_fn=_die_with_parent,
    )
    master = rosgraph.Master("/roboscript_launch", master_uri=uri)
    deadline = time.monotonic() + 30
    while True:
        try:
            pid = master.getPid()
        except OSError:
            pid = None
        if pid == process.pid:
            return process, uri, ""
        exit_code = process.poll()
        if pid is not None:
            why = f"port {port} is another master's (pid {pid})"
        elif exit_code is not None:
            why = f"rosmaster on port {port} exited with {exit_code}"
        elif time.monotonic() > deadline:
            why = f"rosmaster on port {port} did not answer within 30 s"
        else:
            time.sleep(0.05)
            continue
        process.kill()
        process.wait()
        return None, uri, why


@dataclass
class SimProcess:
    """`roboscript ros-sim` running in a subprocess; its output is kept for error messages."""

    process: subprocess.Popen
    output: list[str] = field(default_factory=list)

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()


def start_sim(
    world: str,
    robot: str,
    master_uri: str,
    real_time_factor: float = 2.0,
    seed: int = 0,
    randomize: bool = False,
    task: str | None = None,
    suite: str | None = None,
    extra: tuple[str, ...] = (),
) -> SimProcess:
    """`roboscript ros-sim` on the master at ``master_uri``, once it serves (its output says so)."""
    command = [sys.executable, "-m", "roboscript.cli", "ros-sim", world, "--robot", robot]
    command += ["--real-time-factor", str(real_time_factor), "--seed", str(seed)]
    command += ["--randomize"] if randomize else []
    command += ["--task", task] if task else []
    command += ["--suite", suite] if suite else []
    command += list(extra)
    env = {**os.environ, "ROS_MASTER_URI": master_uri, "ROS_IP": "127.0.0.1"}
    process = subprocess.Popen(
        command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, preexec_fn=_die_with_parent
    )
    sim = SimProcess(process)
    ready = threading.Event()

    def read() -> None:
        for line in process.stdout:
            sim.output.append(line)
            if "serving" in line:
                ready.set()

    threading.Thread(target=read, daemon=True).start()
    deadline = time.monotonic() + START_TIMEOUT
    while not ready.wait(timeout=0.2):
        if process.poll() is not None or time.monotonic() > deadline:
            sim.stop()
            raise DriverError("ros-sim did not start:\n" + "".join(sim.output[-30:]))
    return sim


def evaluate_on_twin(timeout: float = 30.0) -> list[dict]:
    """Asks the running ros-sim (started with ``--task``) to evaluate the task's checks on its own state; the
    checks' results as :meth:`Check.evaluate` gives them. The harness's business: the backend never asks."""
    import rospy
    from std_msgs.msg import String

    asked = uuid.uuid4().hex
    answer: dict = {}
    got = threading.Event()

    def on_answer(message) -> None:
        data = json.loads(message.data)
        if data.get("id") == asked:
            answer.update(data)
            got.set()

    subscriber = rospy.Subscriber(EVALUATION_TOPIC, String, on_answer, queue_size=5)
    publisher = rospy.Publisher(EVALUATE_TOPIC, String, queue_size=5, latch=True)
    try:
        deadline = time.monotonic() + timeout
        while not got.is_set():
            publisher.publish(String(data=json.dumps({"id": asked})))
            if got.wait(timeout=0.5):
                break
            if time.monotonic() > deadline:
                raise DriverError(f"the twin did not evaluate the task's checks within {timeout:.0f} s")
    finally:
        subscriber.unregister()
        publisher.unregister()
    if "error" in answer:
        raise DriverError(f"the twin could not evaluate the checks: {answer['error']}")
    return answer["checks"]
