"""A trial's recording: an MCAP file (the ``record`` extra) a person scrubs through in Foxglove.

On the timeline (simulated time): each camera's images (every ``image_period`` seconds, with its calibration and
pose, so the 3D panel projects them), the TCP's frame and the joints (every ``state_period``), every tool call with
its arguments and its answer or error (``/tool_calls``, and as log lines on ``/log``), after each call the objects
as perception knows them (``/perception/objects``) and the planning scene's obstacles (``/planning_scene``), every
trajectory sent to the arm as the TCP's planned path (``/paths/planned``), the path the TCP really took
(``/paths/executed``) and, at the end, the checks (``/checks``).

:func:`read_recording` reads one back.
"""

from __future__ import annotations

import functools
import io
import json
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np

from roboscript import extras
from roboscript.record import foxglove as fg

# Schema names of the channels: Foxglove's own types where one fits, the project's where none does.
TOPICS = {
    "/tool_calls": "roboscript.ToolCall",
    "/checks": "roboscript.Checks",
    "/joint_states": "roboscript.JointStates",
    "/log": "foxglove.Log",
    "/tf": "foxglove.FrameTransform",
    "/perception/objects": "foxglove.SceneUpdate",
    "/planning_scene": "foxglove.SceneUpdate",
    "/paths/planned": "foxglove.SceneUpdate",
    "/paths/executed": "foxglove.SceneUpdate",
}
OBJECT_RGBA = (0.2, 0.6, 1.0, 0.35)
OBSTACLE_RGBA = (0.6, 0.6, 0.6, 0.25)
PLANNED_RGBA = (1.0, 0.6, 0.1, 1.0)
EXECUTED_RGBA = (0.1, 0.9, 0.3, 1.0)
MAX_TEXT = 2000  # characters of an argument or answer kept in a tool call's message


def _writer_class():
    try:
        from mcap.writer import Writer
    except ImportError:
        raise extras.missing("record", "--record") from None
    return Writer


def _text(value: object) -> str:
    """``value`` as a line of the recording, cut at ``MAX_TEXT`` characters (a program's arguments are its own)."""
    if isinstance(value, np.ndarray):
        value = np.round(value, 4).tolist()
    try:
        text = json.dumps(value, default=str)
    except (TypeError, ValueError):
        text = repr(value)
    return _cut(text)


def _cut(text: str) -> str:
    return text if len(text) <= MAX_TEXT else text[:MAX_TEXT] + "..."


class TrialRecording:
    """Records a trial on ``backend`` with ``tools`` (a :class:`~roboscript.api.tools.ToolAPI`) into ``path``
    while open; :meth:`wrap` gives the program's namespace whose tool calls are recorded."""

    def __init__(self, backend, tools, path: str | Path, image_period: float = 1.0, state_period: float = 0.05):
        writer_class = _writer_class()
        self.backend, self.tools = backend, tools
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file = self.path.open("wb")
        self._writer = writer_class(self._file)
        self._writer.start(profile="", library="roboscript")
        self._channels: dict[str, int] = {}
        self._schemas: dict[str, int] = {}
        self.image_period, self.state_period = image_period, state_period
        self._executed: list[np.ndarray] = []
        self._planned = 0
        self._calls = 0
        self._cameras = self._camera_setup()
        now = backend.time()
        self._next_image, self._next_state = now, now
        self._original_execute = backend.execute_trajectory
        backend.execute_trajectory = self._execute  # an instance attribute: the class is untouched
        backend.add_clock_listener(self._on_tick)
        self._on_tick(now)
        self._snapshot(now)

    # --- writing ---------------------------------------------------------------------------------------------

    def _channel(self, topic: str, schema: str) -> int:
        if topic not in self._channels:
            if schema not in self._schemas:
                data = json.dumps({"title": schema, "type": "object"}).encode()
                self._schemas[schema] = self._writer.register_schema(schema, "jsonschema", data)
            self._channels[topic] = self._writer.register_channel(topic, "json", self._schemas[schema])
        return self._channels[topic]

    def write(self, topic: str, time: float, message: dict, schema: str | None = None) -> None:
        """Writes ``message`` on ``topic`` at simulated ``time``."""
        channel = self._channel(topic, schema or TOPICS[topic])
        stamp = max(0, round(time * 1e9))
        self._writer.add_message(channel, log_time=stamp, data=json.dumps(message).encode(), publish_time=stamp)

    # --- what is recorded ------------------------------------------------------------------------------------

    def _camera_setup(self) -> list[tuple[str, int, int]]:
        cameras = []
        now = self.backend.time()
        for name in self.backend.camera_names():
            frame = self.backend.capture(name, color=False)
            height, width = frame.depth.shape
            k = frame.intrinsics
            fovy = float(np.degrees(2 * np.arctan(height / 2 / k[1, 1])))
            self.write(f"/camera/{name}/calibration", now, fg.camera_calibration(now, name, width, height, fovy),
                       "foxglove.CameraCalibration")  # fmt: skip
            self.write("/tf", now, fg.frame_transform(now, name, frame.extrinsics))
            cameras.append((name, width, height))
        return cameras

    def _on_tick(self, time: float) -> None:
        if time >= self._next_state:
            self._next_state = time + self.state_period
            tcp = self.backend.tcp_pose()
            self._executed.append(np.asarray(tcp.position, dtype=float).copy())
            self.write("/tf", time, fg.frame_transform(time, "tcp", tcp))
            states = self.backend.joint_states()
            self.write("/joint_states", time, {"time": time, "name": list(states), "position": list(states.values())})
        if time >= self._next_image:
            self._next_image = time + self.image_period
            for name, width, height in self._cameras:
                self.write(f"/camera/{name}/image", time, fg.compressed_image(time, name, self._jpeg(name, width,
                           height)), "foxglove.CompressedImage")  # fmt: skip

    def _jpeg(self, camera: str, width: int, height: int) -> bytes:
        from PIL import Image

        buffer = io.BytesIO()
        Image.fromarray(self.backend.render(camera, width, height)).save(buffer, format="JPEG", quality=80)
        return buffer.getvalue()

    def _execute(self, trajectory):
        """The backend's ``execute_trajectory``, with the trajectory recorded as the TCP's planned path first."""
        now = self.backend.time()
        kinematics = self.tools.motion.kinematics
        rows = trajectory.positions[:: max(1, len(trajectory.positions) // 100)]
        points = np.array([kinematics.fk(q).position for q in np.vstack([rows, trajectory.positions[-1:]])])
        self._planned += 1
        line = fg.line_strip(points, PLANNED_RGBA)
        self.write("/paths/planned", now, fg.scene_update([fg.entity(now, f"planned_{self._planned}", lines=[line])]))
        return self._original_execute(trajectory)

    def _snapshot(self, time: float) -> None:
        """The objects as perception knows them, the planning scene's obstacles and the path taken so far."""
        perception = self.tools.perception
        cubes, texts = [], []
        for name in perception.names():
            try:
                box = perception.box(name)
            except Exception:  # a name known but not seen yet: nothing to draw
                continue
            cubes.append(fg.box_cube(box, OBJECT_RGBA))
            texts.append(fg.label(name, [*box.center[:2], box.upper[2] + 0.02]))
        clear = [fg.delete_all(time)]
        objects = fg.scene_update([fg.entity(time, "objects", cubes, texts=texts)], clear)
        self.write("/perception/objects", time, objects)
        from roboscript.planning.scene_boxes import obstacle_boxes

        scene = self.tools.motion.scene  # as last brought up to date by a motion: recording must change nothing
        obstacles = [fg.box_cube(b, OBSTACLE_RGBA) for b in obstacle_boxes(scene).values()]
        self.write("/planning_scene", time, fg.scene_update([fg.entity(time, "obstacles", obstacles)], clear))
        if len(self._executed) > 1:
            line = fg.line_strip(np.array(self._executed), EXECUTED_RGBA)
            self.write("/paths/executed", time, fg.scene_update([fg.entity(time, "executed", lines=[line])], clear))

    def _record_call(self, name: str, args: tuple, kwargs: dict, started: float, answer=None, error=None) -> None:
        now = self.backend.time()
        self._calls += 1
        arguments = [_text(a) for a in args] + [f"{k}={_text(v)}" for k, v in kwargs.items()]
        message = {"index": self._calls, "tool": name, "arguments": arguments, "started": started, "ended": now,
                   "answer": None if error else _text(answer), "error": error}  # fmt: skip
        self.write("/tool_calls", started, message)
        outcome = f"error: {error}" if error else f"-> {message['answer']}"
        self.write("/log", started, fg.log(started, "error" if error else "info", name,
                                           f"{name}({', '.join(arguments)}) {outcome}"))  # fmt: skip
        self._snapshot(now)

    def wrap(self, namespace: dict) -> dict:
        """A copy of ``namespace`` whose tools record each call."""
        from roboscript.api.tools import ToolAPI

        wrapped = dict(namespace)
        for name in ToolAPI.TOOL_NAMES:
            if name in namespace:
                wrapped[name] = self._recorded(name, namespace[name])
        return wrapped

    def _recorded(self, name: str, function: Callable) -> Callable:
        @functools.wraps(function)
        def call(*args, **kwargs):
            started = self.backend.time()
            try:
                answer = function(*args, **kwargs)
            except BaseException as exc:
                error = _cut(f"{type(exc).__name__}: {exc}")
                self._record_call(name, args, kwargs, started, error=error)
                raise
            self._record_call(name, args, kwargs, started, answer=answer)
            return answer

        return call

    def log_checks(self, checks: list[dict]) -> None:
        now = self.backend.time()
        self.write("/checks", now, {"time": now, "checks": checks})

    def close(self) -> None:
        if self._writer is None:
            return
        self.backend.remove_clock_listener(self._on_tick)
        self.backend.execute_trajectory = self._original_execute
        self._snapshot(self.backend.time())
        self._writer.finish()
        self._file.close()
        self._writer = None


def read_recording(path: str | Path) -> Iterator[tuple[str, float, dict]]:
    """``(topic, simulated time, message)`` for every message of a recording, in time order."""
    from mcap.reader import make_reader

    with Path(path).open("rb") as f:
        for _schema, channel, message in make_reader(f).iter_messages(log_time_order=True):
            yield channel.topic, message.log_time / 1e9, json.loads(message.data)
