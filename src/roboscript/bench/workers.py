"""Trial workers: long-lived processes, one per job, that keep what trials share and fork each trial from there.

Every trial still runs in a process of its own: a program that crashes the interpreter or never returns costs that
trial only, and OMPL's sampling is seeded afresh in each. But the trial is forked from a worker that has already
made what the trials of a world ask for and can keep: the world compiled (:func:`roboscript.sim.world.build_world`
keeps it), the robot's model compiled alone at the world's mount (for the kinematics), and, where the GL driver
allows keeping GL state across a fork (:func:`roboscript.sim.shared_gl.fork_safe`), the renderers of the world's
cameras with their shaders compiled. A trial then finds them made instead of spending half a second on them.

The worker and the runner speak over one pipe. The runner sends a :class:`TrialSpec` (or ``None``: stop); the
worker answers ``("started", pid)`` with the trial's process id, ``("stage", text)`` each time the trial says what it
is doing (building the world, asking the LLM, running the program), then ``("ok", record)``, ``("error", text)``,
``("died", exit code)`` or ``("timeout", text)``.

The worker is also the trial's watchdog. The trial tells it, over the pipe it reports on, by when the program it
is running must be over (``("deadline", t)``, then ``("deadline", None)`` once it is); a trial still inside that
run past the deadline and :data:`WATCHDOG_MARGIN` is stuck where its own timer cannot reach (a tool in native code
that never returns), and is killed and reported as a time-out.
"""

from __future__ import annotations

import contextlib
import functools
import os
import pickle
import resource
import select
import signal
import struct
import sys
import time
import traceback
from collections.abc import Callable

from roboscript.bench.trial import TrialSpec, run_trial
from roboscript.codegen.sandbox import address_space
from roboscript.processes import die_with_parent, run_exit_hooks

LENGTH = struct.Struct("<Q")  # the length of a trial's message, before it
POLL_INTERVAL = 0.5  # seconds between looks at whether a trial that has not reported has ended
WATCHDOG_MARGIN = 5.0  # seconds past a program's announced end before its trial is killed


def serve(conn, run: Callable[[TrialSpec], dict] | None = None, warm: Callable[[TrialSpec], None] | None = None):
    """A worker's loop: for each spec from ``conn``, warm this process for it, fork the trial, report.

    ``run`` (default: :func:`run_trial`, as a dict) runs a trial in the forked process, ``warm`` (default:
    :func:`warm_for`) prepares this one; both are parameters for the runner's tests."""
    run = run or _run_trial
    warm = warm or warm_for
    from roboscript.sim import shared_gl

    os.environ.setdefault(shared_gl.SOFTWARE_GL_THREADS, "0")  # before any GL is made here; a user's choice stands

    if shared_gl.fork_safe():
        shared_gl.share_renderers()
    try:
        while True:
            try:
                spec = conn.recv()
            except EOFError:  # the runner is gone
                return
            if spec is None:
                return
            with contextlib.suppress(Exception):  # the trial meets the same problem and reports it as its own
                warm(spec)
            _fork_trial(conn, spec, run)
    except KeyboardInterrupt:  # Ctrl-C reaches the whole process group; the runner cleans up
        return


def _fork_trial(conn, spec: TrialSpec, run: Callable[[TrialSpec], dict]) -> None:
    reader, writer = os.pipe()
    parent = os.getpid()
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:
        os.close(reader)
        die_with_parent(parent=parent)
        _trial_child(spec, run, writer)
    os.close(writer)
    conn.send(("started", pid))
    payload, status, overdue = _outcome(reader, pid, lambda text: conn.send(("stage", text)))
    if payload is not None:
        conn.send(pickle.loads(payload))
    elif overdue is not None:
        conn.send(("timeout", overdue))
    else:
        conn.send(("died", os.waitstatus_to_exitcode(status)))


def _outcome(
    reader: int, pid: int, on_stage: Callable[[str], None] = lambda text: None
) -> tuple[bytes | None, int, str | None]:
    """The trial's final message (None if it ended without one), its wait status, and why the watchdog killed it
    (None if it did not); ``on_stage`` gets each stage the trial reports. Reads until the final message is whole or
    the trial has ended, not until the pipe's end: a process the trial started may still hold the pipe open."""
    frames = _Frames()
    deadline: float | None = None
    status = None
    try:
        while status is None:
            if select.select([reader], [], [], POLL_INTERVAL)[0]:
                chunk = os.read(reader, 1 << 20)
                if not chunk:
                    break
                for frame in frames.add(chunk):
                    if frame[:1] == b"D":  # a deadline frame: the program's run must be over by then
                        deadline = _deadline(frame)
                    elif frame[:1] == b"S":  # a stage frame: what the trial is doing now
                        on_stage(frame[1:].decode(errors="replace"))
                    else:
                        return frame, os.waitpid(pid, 0)[1], None
                continue
            if deadline is not None and time.monotonic() > deadline + WATCHDOG_MARGIN:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
                why = (
                    "TimeoutError: the program ran past its limit and a tool it called did not return (the trial's "
                    f"process was killed {WATCHDOG_MARGIN:g} s after the program's deadline)"
                )
                return None, 0, why
            done, reaped = os.waitpid(pid, os.WNOHANG)
            if done:
                status = reaped
                while select.select([reader], [], [], 0)[0] and (chunk := os.read(reader, 1 << 20)):
                    for frame in frames.add(chunk):  # what it wrote just before it ended
                        if frame[:1] not in (b"D", b"S"):
                            return frame, status, None
    finally:
        os.close(reader)
    if status is None:
        status = os.waitpid(pid, 0)[1]
    return None, status, None


class _Frames:
    """Splits what the trial writes into its length-prefixed frames."""

    def __init__(self):
        self.received = bytearray()

    def add(self, chunk: bytes) -> list[bytes]:
        self.received += chunk
        frames = []
        while len(self.received) >= LENGTH.size:
            (length,) = LENGTH.unpack_from(self.received)
            if len(self.received) - LENGTH.size < length:
                break
            frames.append(bytes(self.received[LENGTH.size : LENGTH.size + length]))
            del self.received[: LENGTH.size + length]
        return frames


def _deadline(frame: bytes) -> float | None:
    text = frame[1:].decode()
    return None if text == "none" else float(text)


def _write_frame(writer: int, data: bytes) -> None:
    view = memoryview(LENGTH.pack(len(data)) + data)
    while view:
        view = view[os.write(writer, view) :]


def _trial_child(spec: TrialSpec, run: Callable[[TrialSpec], dict], writer: int) -> None:
    """In the forked trial: run it, write the outcome to the worker, and leave without the worker's clean-up."""
    code = 1
    global _announce, _stage
    _announce = functools.partial(_announce_deadline, writer)
    _stage = functools.partial(_report_stage, writer)
    _limit_memory(TRIAL_MEMORY)
    # Whatever a trial's libraries print (a tool's notice, a planner's log line) goes to stderr: the command's
    # stdout carries its own output alone (one JSON document with --json).
    sys.stdout.flush()
    os.dup2(2, 1)
    try:
        try:
            message = ("ok", run(spec))
        except BaseException as exc:  # the world could not be built, or judging failed: report, do not hang
            message = ("error", f"{type(exc).__name__}: {exc}\n{traceback.format_exc(limit=4)}")
        _write_frame(writer, pickle.dumps(message))  # a pickle starts with b"\x80", never with b"D" or b"S"
        code = 0
    finally:
        run_exit_hooks()  # what the trial started that ends with its process (a ROS trial's master and its home)
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)


_announce: Callable[[float | None], None] | None = None  # in a trial's process: tells the worker its deadline
_stage: Callable[[str], None] | None = None  # in a trial's process: tells the worker what the trial is doing

# Address space a trial's process may add to what it was forked with: simulation, perception and planning for one
# trial take about 2 GiB; a tool driven into unbounded work fails with a MemoryError well before the machine does.
TRIAL_MEMORY = 12 * 1024**3


def _limit_memory(extra: int) -> None:
    mapped = address_space()
    if mapped is None:
        return
    hard = resource.getrlimit(resource.RLIMIT_AS)[1]
    limit = mapped + extra if hard == resource.RLIM_INFINITY else min(mapped + extra, hard)
    resource.setrlimit(resource.RLIMIT_AS, (limit, hard))


def _announce_deadline(writer: int, deadline: float | None) -> None:
    _write_frame(writer, b"D" + (b"none" if deadline is None else repr(deadline).encode()))


def _report_stage(writer: int, text: str) -> None:
    _write_frame(writer, b"S" + text.encode())


def _run_trial(spec: TrialSpec) -> dict:
    return run_trial(spec, announce=_announce, stage=_stage).to_dict()


def warm_for(spec: TrialSpec) -> None:
    """Makes in this process, once, what the trial of ``spec`` will ask for and may keep: the world compiled, the
    robot compiled alone at the world's mount and, where renderers are shared, the renderers its cameras and video
    will use. Any build of the world will do: the trial's seed only moves its objects."""
    if spec.backend != "mujoco":
        return
    from roboscript.bench.tasks import get_task
    from roboscript.robots import get_robot
    from roboscript.robots.mujoco_model import compiled_robot
    from roboscript.sim.shared_gl import sharing
    from roboscript.sim.world import build_world, robot_mount
    from roboscript.sim.world_catalog import load_world

    world = load_world(spec.world if spec.world else get_task(spec.task, spec.suite).world)
    description = get_robot(spec.robot or world.robot)
    compiled_robot(description, robot_mount(world, description))
    built = build_world(world, spec.robot)
    if sharing():
        _warm_renderers(spec, built)


def _warm_renderers(spec: TrialSpec, built) -> None:
    """The renderers a trial in ``built``'s world will ask for, each used once (the rasteriser compiles its
    shaders at the first renders)."""
    from roboscript.bench.video import VIDEO_SIZE
    from roboscript.sim.cameras import Renderer

    colour = spec.perception.observed_objects  # the camera pipeline captures colour; ground truth, depth only
    sizes = {(c.width, c.height, colour): c.name for c in built.spec.cameras}
    if spec.video:
        sizes[(*VIDEO_SIZE, True)] = spec.video_camera
    for (width, height, smooth), camera in sizes.items():
        renderer = Renderer(built.model, built.geom_entity, width, height, antialiasing=smooth)
        renderer.depth_and_segmentation(built.data, camera)
        if smooth:
            renderer.rgb(built.data, camera)
