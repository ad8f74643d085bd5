"""Starts a franky-sim server in a process of its own (its 1 kHz loop must not share this interpreter's lock) and
stops it."""

from __future__ import annotations

import collections
import json
import queue
import subprocess
import sys
import threading
import time
from collections.abc import Sequence

import numpy as np

from roboscript.errors import FailureError

START_TIMEOUT = 120.0  # seconds for the server to compile its model and bind (a busy 2-core machine is slow)


class FrankySimError(FailureError, RuntimeError):
    """franky-sim could not be started."""


class FrankySim:
    """A running franky-sim server; ``host`` is the loopback address it serves libfranka's protocol on."""

    def __init__(
        self,
        base: Sequence[float] | None = None,
        joints: Sequence[float] | None = None,
        world: str | None = None,
        seed: int | None = None,
    ):
        """An FR3 alone with its base at ``base`` (default: the origin), or in ``world`` (a world's name or file:
        its scene, with the arm where the world stands it); ``joints``: where the arm starts (default: franky-sim's,
        or the FR3's home in a world); ``seed``: the world laid out as a benchmark trial of that seed lays it out."""
        if base is not None and world is not None:
            raise ValueError("base is for an arm alone: a world stands its arm where its file says")
        command = [sys.executable, "-m", "roboscript.frankysim.server"]
        if base is not None:
            command += ["--base", *map(_number, base)]
        if joints is not None:
            command += ["--joints", *map(_number, joints)]
        if world is not None:
            command += ["--world", world] + (["--seed", str(seed)] if seed is not None else [])
        self._process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
        )
        # Its output is read for as long as it runs: a full pipe would block the server's 1 kHz loop.
        self._output: collections.deque[str] = collections.deque(maxlen=50)
        self._serving = threading.Event()
        self._host = ""
        self._states: queue.Queue[str] = queue.Queue()
        self._asking = threading.Lock()
        self._reader = threading.Thread(target=self._read_output, daemon=True)
        self._reader.start()
        self.host = self._wait_for_host()

    def _read_output(self) -> None:
        for line in self._process.stdout:
            if line.startswith("state "):
                self._states.put(line[len("state ") :])
                continue
            self._output.append(line.rstrip())
            if line.startswith("serving "):
                self._host = line.split()[1]
                self._serving.set()

    def _wait_for_host(self) -> str:
        deadline = time.monotonic() + START_TIMEOUT
        while not self._serving.wait(0.2):
            ended = self._process.poll() is not None
            if ended or time.monotonic() > deadline:
                self.stop()
                self._reader.join(timeout=2.0)  # until it has read the server's last lines
                said = "\n".join(list(self._output)[-10:]) or "no output"
                why = (
                    f"ended (exit status {self._process.returncode})"
                    if ended
                    else f"did not start within {START_TIMEOUT:.0f} s"
                )
                raise FrankySimError(f"franky-sim {why}: {said}")
        return self._host

    def state(self, timeout: float = 10.0) -> tuple[np.ndarray, np.ndarray]:
        """The served world's joint positions and velocities now (started with a ``world`` only)."""
        with self._asking:
            try:
                self._process.stdin.write("state\n")
                self._process.stdin.flush()
                answer = self._states.get(timeout=timeout)
            except (OSError, queue.Empty):
                said = "\n".join(list(self._output)[-5:])
                raise FrankySimError(f"franky-sim gave no state within {timeout:.0f} s (did it end? {said})") from None
        qpos, qvel = json.loads(answer)
        return np.array(qpos), np.array(qvel)

    def trip_reflex(self) -> None:
        """Makes the arm's running motion (or its next) end in a joint reflex, as a collision would on an FR3."""
        try:
            self._process.stdin.write("reflex\n")
            self._process.stdin.flush()
        except OSError:
            said = "\n".join(list(self._output)[-5:])
            raise FrankySimError(f"franky-sim is not running to trip a reflex in ({said})") from None

    def stop(self) -> None:
        """Ends the server (closing its standard input is its signal), killing it if it does not end in 10 s."""
        if self._process.poll() is None:
            try:
                self._process.stdin.close()
                self._process.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self._process.kill()
                self._process.wait()

    def __enter__(self) -> FrankySim:
        return self

    def __exit__(self, *exc) -> None:
        self.stop()


def _number(value: float) -> str:
    """A number as an argument: fixed-point, since argparse takes ``-1e-05`` for an option, not a negative number."""
    return f"{float(value):.9f}"
