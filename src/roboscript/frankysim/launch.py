"""Starts a franky-sim server in a process of its own (its 1 kHz loop must not share this interpreter's lock) and
stops it."""

from __future__ import annotations

import subprocess
import sys
import threading
from collections.abc import Sequence

from roboscript.errors import FailureError

START_TIMEOUT = 120.0  # seconds for the server to compile its model and bind (a busy 2-core machine is slow)


class FrankySimError(FailureError, RuntimeError):
    """franky-sim could not be started."""


class FrankySim:
    """A running franky-sim server; ``host`` is the loopback address it serves libfranka's protocol on."""

    def __init__(self, base: Sequence[float] = (0.0, 0.0, 0.0), joints: Sequence[float] | None = None):
        command = [sys.executable, "-m", "roboscript.frankysim.server", "--base", *map(str, base)]
        if joints is not None:
            command += ["--joints", *map(str, joints)]
        self._process = subprocess.Popen(
            command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        self.host = self._wait_for_host()

    def _wait_for_host(self) -> str:
        lines: list[str] = []
        reader = threading.Thread(target=lambda: lines.append(self._process.stdout.readline()), daemon=True)
        reader.start()
        reader.join(START_TIMEOUT)
        line = lines[0].strip() if lines else ""
        if not line.startswith("serving "):
            self.stop()
            error = self._process.stderr.read()[-2000:] if self._process.stderr else ""
            raise FrankySimError(
                f"franky-sim did not start within {START_TIMEOUT:.0f} s: {line or error or 'no output'}"
            )
        return line.split()[1]

    def stop(self) -> None:
        if self._process.poll() is None:
            try:
                self._process.stdin.close()  # the server's signal to end
                self._process.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                self._process.kill()
                self._process.wait()

    def __enter__(self) -> FrankySim:
        return self

    def __exit__(self, *exc) -> None:
        self.stop()
